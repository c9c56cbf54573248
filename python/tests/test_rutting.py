"""vrut.rutting() against vrut-rutting: the same inputs give the same numbers,
to the last bit, and the same errors."""
import json
import os
import re
import signal
import subprocess
import threading
import time

import numpy
import pytest

import vrut
from conftest import TINY, as_args, check_summary

# A short 2D run (a 100 mm section, about 3 s on one thread), one thread so
# that runs compare bit for bit whatever the machine.
SMALL = dict(gradation=2, seed=1, width_mm=100, threads=1)
SMALL_ARGS = ["--gradation", "2", "--seed", "1", "--width-mm", "100", "--threads", "1"]
# conftest.TINY where a test compares two runs with each other.
TINY_ARGS = as_args(TINY)
# What differs between two runs of one input: the clock, and what it gives.
CLOCK = {"wall_seconds", "particle_steps_per_second"}


def run_cli(cli, args, tmp_path, name="cli"):
    out = tmp_path / name
    done = subprocess.run([cli, *args, "--out", str(out)], capture_output=True, text=True)
    return done, out


def without_clock(summary):
    return {k: v for k, v in summary.items() if k not in CLOCK}


@pytest.fixture(scope="module")
def uninterrupted(cli, tmp_path_factory):
    """The command line's SMALL run, to its end: the folder of its results."""
    done, out = run_cli(cli, SMALL_ARGS, tmp_path_factory.mktemp("uninterrupted"))
    assert done.returncode == 0, done.stderr
    return out


@pytest.fixture(scope="module")
def uninterrupted_tiny(cli, tmp_path_factory):
    """The command line's TINY run, to its end: the folder of its results."""
    done, out = run_cli(cli, TINY_ARGS, tmp_path_factory.mktemp("uninterrupted_tiny"))
    assert done.returncode == 0, done.stderr
    return out


def test_same_numbers_and_files_as_the_command_line(uninterrupted, tmp_path):
    out = uninterrupted
    expected = json.loads((out / "summary.json").read_text())
    check_summary(expected)  # a 2D run
    run = vrut.rutting(out=tmp_path / "py", **SMALL)
    # Every double of summary.json, as the command line wrote it (JSON keeps 17 digits).
    assert without_clock(run.summary) == without_clock(expected)
    assert run.rut_depth_mm == expected["rut_depth_mm"]
    # Regression pin (e4e7f74's vrut-rutting, before the application layer
    # moved into the library): the same run's rut depth, to the last bit.
    assert expected["rut_depth_mm"] == 9.44896625473758
    assert run.dynamic_stability == expected["dynamic_stability_passes_per_mm"]
    # The module's folder holds the command line's files, the curve bit for bit.
    assert (tmp_path / "py" / "deformation.csv").read_bytes() == (out / "deformation.csv").read_bytes()
    written = json.loads((tmp_path / "py" / "summary.json").read_text())
    assert without_clock(written) == without_clock(expected)
    # The curve as arrays: the file's columns, read independently.
    table = numpy.genfromtxt(out / "deformation.csv", delimiter=",", names=True)
    assert numpy.array_equal(run.minutes, table["minutes"])
    assert numpy.array_equal(run.deformation_mm, table["deformation_mm"])
    assert run.deformation_mm[-1] == expected["rut_depth_mm"]


def test_a_3d_run_is_the_command_lines(cli, tmp_path):
    # A small box of 2 mm spheres (about 1,500 of them), a short settling and
    # a large time shift: the 3D path end to end, as the command line runs it.
    # 1#'s stones place in a fraction of a second here, 2#'s take seconds.
    small3 = dict(dim=3, gradation=1, width_mm=40, sphere_radius_mm=2, shift=2e5, settle_steps=300, seed=1, threads=1)
    args = as_args(small3)
    done, out = run_cli(cli, args, tmp_path)
    assert done.returncode == 0, done.stderr
    expected = json.loads((out / "summary.json").read_text())
    assert expected["dimension"] == 3
    check_summary(expected)  # a 3D run
    run = vrut.rutting(out=tmp_path / "py", **small3)
    assert without_clock(run.summary) == without_clock(expected)
    assert (tmp_path / "py" / "deformation.csv").read_bytes() == (out / "deformation.csv").read_bytes()


def test_float_options_reach_the_run_exactly(cli, tmp_path):
    # A value with no short decimal form: the module must pass it without rounding.
    eta1 = 83.34 * (1.0 + 2.0 ** -40)
    done, out = run_cli(cli, TINY_ARGS + ["--eta1", repr(eta1), "--minutes", "46"], tmp_path)
    assert done.returncode == 0, done.stderr
    expected = json.loads((out / "summary.json").read_text())
    run = vrut.rutting(eta1=eta1, minutes=46, **TINY)
    assert without_clock(run.summary) == without_clock(expected)


def test_numpy_scalars_and_seed_lists():
    # A sweep over numpy.linspace passes numpy scalars: the same run as Python's floats.
    a = vrut.rutting(eta1=numpy.float64(60.0), minutes=numpy.int64(46), **TINY)
    b = vrut.rutting(eta1=60.0, minutes=46, **TINY)
    assert numpy.array_equal(a.deformation_mm, b.deformation_mm)
    with pytest.raises(ValueError, match="no seeds"):
        vrut.rutting(seeds=[], width_mm=100)
    with pytest.raises(TypeError, match="whole numbers"):
        vrut.rutting(seeds=[1.5], width_mm=100)


def test_an_ensemble_equals_its_single_runs():
    one_seed = {k: v for k, v in TINY.items() if k != "seed"}
    both = vrut.rutting(seeds=[1, 2], **one_seed)
    assert both.seeds == [1, 2]
    check_summary(both.summary)  # an ensemble
    for k, seed in enumerate((1, 2)):
        alone = vrut.rutting(seed=seed, **one_seed)
        assert numpy.array_equal(both.curves_mm[k], alone.deformation_mm)
        assert both.per_seed[k]["rut_depth_mm"] == alone.rut_depth_mm
    # The mean curve is the specimens' mean, sample by sample.
    assert numpy.allclose(both.deformation_mm, both.curves_mm.mean(axis=0), rtol=1e-15, atol=0)
    # The 95 % interval of the mean at each sample, worked here: Student's t
    # for one degree of freedom, 12.7062047 (tables), times the sample
    # standard deviation over sqrt(2).
    low, high = both.ci95_mm
    half = 12.706204736174707 * both.curves_mm.std(axis=0, ddof=1) / numpy.sqrt(2.0)
    assert numpy.allclose(low, both.deformation_mm - half, rtol=1e-9, atol=1e-12)
    assert numpy.allclose(high, both.deformation_mm + half, rtol=1e-9, atol=1e-12)
    assert numpy.all(half[1:] > 0.0)  # two specimens, two curves


@pytest.mark.parametrize("kwargs, args", [
    (dict(eta1=-1.0), ["--eta1", "-1.0"]),
    (dict(air_voids=0.5), ["--air-voids", "0.5"]),
    (dict(stone_film="thick"), ["--stone-film", "thick"]),
    (dict(seeds="3-1"), ["--seeds", "3-1"]),
    (dict(dim=3, disk_radius_mm=0.5), ["--dim", "3", "--disk-radius-mm", "0.5"]),
    (dict(least_film="thin"), ["--least-film", "thin"]),
])
def test_bad_input_raises_the_command_lines_message(cli, tmp_path, kwargs, args):
    done, _ = run_cli(cli, args, tmp_path)
    assert done.returncode == 2
    message = done.stderr.splitlines()[0]
    message = message[len("error: "):] if message.startswith("error: ") else message
    with pytest.raises(ValueError) as raised:
        vrut.rutting(**kwargs)
    assert str(raised.value) == message


def test_unknown_or_reserved_keywords_are_type_errors():
    with pytest.raises(TypeError, match="unexpected keyword argument 'width'"):
        vrut.rutting(width=100)
    with pytest.raises(TypeError, match="resume"):
        vrut.rutting(resume="out")
    with pytest.raises(TypeError, match="switch"):
        vrut.rutting(exact_stones="yes")


def test_progress_reaches_the_end():
    seen = []
    vrut.rutting(progress=seen.append, **TINY)
    assert seen and seen[-1] == pytest.approx(1.0, abs=1e-3)
    assert all(a <= b for a, b in zip(seen, seen[1:]))


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM], ids=["ctrl-c", "sigterm"])
def test_a_stopped_run_leaves_a_checkpoint_the_command_line_resumes(cli, uninterrupted_tiny, tmp_path, signum):
    python_handler = signal.getsignal(signum)
    started = threading.Event()

    def progress(fraction):
        if not started.is_set():
            started.set()
            os.kill(os.getpid(), signum)  # as Ctrl-C or a scheduler would, while the loading runs

    # Ctrl-C: KeyboardInterrupt with the way on; SIGTERM: the command line's exit code, 143.
    stop = KeyboardInterrupt if signum == signal.SIGINT else SystemExit
    with pytest.raises(stop, match="vrut-rutting --resume" if stop is KeyboardInterrupt else "^143$") as raised:
        vrut.rutting(out=tmp_path / "stopped", progress=progress, **TINY)
    summary = json.loads((tmp_path / "stopped" / "summary.json").read_text())
    assert summary["interrupted"] is True and summary["minutes_done"] < 60
    check_summary(summary)  # a stopped run
    assert raised.value.run.summary["minutes_done"] == summary["minutes_done"]
    assert (tmp_path / "stopped" / "checkpoint.vrut").exists()
    # Python has its own handler back: Ctrl-C now reaches Python.
    if signum == signal.SIGINT:
        assert signal.getsignal(signum) is python_handler
        with pytest.raises(KeyboardInterrupt):
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(5)
    # The command line goes on from the checkpoint, not from the start, to
    # the uninterrupted run's results to the bit.
    done = subprocess.run([cli, "--resume", str(tmp_path / "stopped")], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    first = re.search(r"resumed: minute ([0-9.]+) of 60", done.stderr)
    assert first, done.stderr
    assert 0.0 < summary["minutes_done"] < float(first.group(1))
    resumed = json.loads((tmp_path / "stopped" / "summary.json").read_text())
    expected = json.loads((uninterrupted_tiny / "summary.json").read_text())
    assert resumed["rut_depth_mm"] == expected["rut_depth_mm"]
    assert resumed["dynamic_stability_passes_per_mm"] == expected["dynamic_stability_passes_per_mm"]
    assert (tmp_path / "stopped" / "deformation.csv").read_bytes() == (uninterrupted_tiny / "deformation.csv").read_bytes()
    assert not (tmp_path / "stopped" / "checkpoint.vrut").exists()


def test_one_kokkos_runtime_per_process():
    vrut.rutting(**TINY)  # Kokkos runs on one thread from here on
    with pytest.raises(ValueError, match="start a new Python process"):
        vrut.rutting(gradation=2, seed=1, width_mm=100, threads=2)


def test_the_schema_refuses_a_summary_that_drifts(uninterrupted):
    # The schema is a check, not a description: each of the two shapes the
    # summaries had before they became one, and a key it does not know, fail.
    summary = json.loads((uninterrupted / "summary.json").read_text())
    for drift in (dict(plate_mm=summary["plate_mm"][0]),  # 2D's plate as one number
                  dict(sphere_radius_mm=1.0),             # a 3D key in a 2D summary
                  dict(plate="patch"),                    # a patch is 3D's
                  dict(undocumented=1)):
        with pytest.raises(AssertionError):
            check_summary({**summary, **drift})
    for key in ("dimension", "calibrated", "dynamic_stability_standard"):
        with pytest.raises(AssertionError, match=key):
            check_summary({k: v for k, v in summary.items() if k != key})
