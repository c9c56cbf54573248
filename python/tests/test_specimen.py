"""vrut.specimen() against the command line's specimen of the same options."""
import json
import subprocess

import numpy

import vrut


def test_specimen_is_the_command_lines(cli, tmp_path):
    out = tmp_path / "cli"
    done = subprocess.run([cli, "--gradation", "3", "--seed", "4", "--width-mm", "100", "--threads", "1",
                           "--shift", "1e5", "--settle-steps", "300", "--out", str(out)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    expected = json.loads((out / "summary.json").read_text())
    sp = vrut.specimen(gradation=3, seed=4, width_mm=100)
    assert sp.summary == expected["specimen"]
    assert len(sp) == expected["particles"]
    assert sp.radius_mm == expected["disk_radius_mm"]
    # Inside the 100 x 50 mm section; the stones' disks (index >= 0, -1 the
    # mastic) as many as the summary counts, the stones' indices below its count.
    assert 0 < sp.x_mm.min() and sp.x_mm.max() < 100 and 0 < sp.y_mm.min() and sp.y_mm.max() < 50
    assert numpy.count_nonzero(sp.stone >= 0) == sp.summary["disks"]["aggregate"]
    assert sp.stone.min() == -1 and sp.stone.max() < sp.summary["aggregate_count"]


def test_a_3d_specimen_has_depth():
    sp = vrut.specimen(dim=3, gradation=1, seed=1, width_mm=30, height_mm=25, sphere_radius_mm=1.5, threads=1)
    assert sp.z_mm is not None and len(sp.z_mm) == len(sp)
    width, height, depth = sp.summary["box_mm"]
    assert (width, height) == (30, 25)
    assert sp.z_mm.min() >= 0 and sp.z_mm.max() < depth and sp.y_mm.max() < height
    assert numpy.count_nonzero(sp.stone >= 0) == sp.summary["spheres"]["in_stones"]
