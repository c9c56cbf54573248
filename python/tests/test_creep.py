"""vrut.creep() against vrut-creep, and against the macro Burger's model."""
import json
import os
import subprocess

import numpy
import pytest

import vrut

SMALL = dict(columns=10, rows=10, time_s=2.0, stress_mpa=0.01, threads=1, E1=4.64, eta1=83.34, E2=0.82, eta2=10.0)
SMALL_ARGS = ["--columns", "10", "--rows", "10", "--time-s", "2.0", "--stress-mpa", "0.01", "--threads", "1",
              "--E1", "4.64", "--eta1", "83.34", "--E2", "0.82", "--eta2", "10.0"]
CLOCK = {"wall_seconds", "particle_steps_per_second"}


def test_creep_is_the_command_lines(cli, tmp_path):
    creep_cli = os.path.join(os.path.dirname(cli), "vrut-creep")
    done = subprocess.run([creep_cli, *SMALL_ARGS, "--out", str(tmp_path / "cli")], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    expected = json.loads((tmp_path / "cli" / "creep.json").read_text())
    run = vrut.creep(out=tmp_path / "py", **SMALL)
    assert {k: v for k, v in run.summary.items() if k not in CLOCK} == \
           {k: v for k, v in expected.items() if k not in CLOCK}
    assert (tmp_path / "py" / "creep.csv").read_bytes() == (tmp_path / "cli" / "creep.csv").read_bytes()
    # The macro curve is Burger's creep law, worked here independently:
    # eps = s (1/E1 + t/eta1 + (1 - exp(-E2 t / eta2)) / E2), t the real time.
    E1, eta1, E2, eta2 = 4.64e6, 83.34e6, 0.82e6, 10e6
    t = run.time_s
    macro = 0.01e6 * (1 / E1 + t / eta1 + (1 - numpy.exp(-E2 * t / eta2)) / E2)
    assert numpy.allclose(run.strain_analytic, macro, rtol=1e-12, atol=0)


def test_bad_creep_input_is_the_command_lines_message():
    with pytest.raises(ValueError, match="^--rows: Value 1 not in range 2 to 2000$"):
        vrut.creep(rows=1)
