"""vrut.Gradation and vrut.Materials: the command line's checks, and the same
runs as the options given one by one."""
import numpy
import pytest

import vrut
from conftest import TINY

# These tests compare two runs of the module with each other: the tiny run serves.
SMALL = {k: v for k, v in TINY.items() if k != "gradation"}
# Mix 2# as docs/method.md section 2 tabulates it.
SIEVES_MM = [19.0, 16.0, 13.2, 9.5, 4.75, 2.36]
MIX2_PASSING = [100, 95, 84, 70, 48, 34]


def test_a_builtin_gradation_is_the_methods_table():
    g = vrut.Gradation(2)
    assert g.sieves_mm == SIEVES_MM and g.percent_passing == MIX2_PASSING


def test_a_table_runs_as_the_builtin_mix_it_copies():
    table = vrut.Gradation(sieves_mm=SIEVES_MM, percent_passing=MIX2_PASSING, name="mix2")
    by_table = vrut.rutting(gradation=table, **SMALL)
    builtin = vrut.rutting(gradation=2, **SMALL)
    assert numpy.array_equal(by_table.deformation_mm, builtin.deformation_mm)
    assert by_table.summary["gradation"].endswith("mix2.csv")


@pytest.mark.parametrize("sieves, passing, reason", [
    (SIEVES_MM, [100, 95, 84, 90, 48, 34], "percent passing must not increase"),
    ([19.0, 16.0, 16.0], [100, 90, 80], "sieve sizes must decrease"),
    ([19.0, 16.0], [95, 90], "the largest sieve must pass 100 %"),
])
def test_a_bad_table_is_refused_with_the_reason(sieves, passing, reason):
    with pytest.raises(ValueError, match=reason):
        vrut.Gradation(sieves_mm=sieves, percent_passing=passing, name="bad")


def test_materials_are_the_options_they_hold():
    soft = vrut.Materials(eta1=60.0, stone_friction=0.3)
    given = vrut.rutting(gradation=2, materials=soft, **SMALL)
    one_by_one = vrut.rutting(gradation=2, eta1=60.0, stone_friction=0.3, **SMALL)
    assert numpy.array_equal(given.deformation_mm, one_by_one.deformation_mm)
    # An option given beside them wins, and the materials' others still hold:
    # the stones' friction comes from `soft` alone, so a module that dropped
    # the materials when given another option would run at the default
    # friction, which gives another curve.
    beside = vrut.rutting(gradation=2, materials=soft, eta1=83.34, **SMALL)
    friction_only = vrut.rutting(gradation=2, stone_friction=0.3, **SMALL)
    assert numpy.array_equal(beside.deformation_mm, friction_only.deformation_mm)
    default = vrut.rutting(gradation=2, **SMALL)
    assert not numpy.array_equal(default.deformation_mm, friction_only.deformation_mm)


def test_materials_are_checked_when_made():
    with pytest.raises(ValueError, match="^--eta1: must be a finite positive number, got -1.0$"):
        vrut.Materials(eta1=-1.0)
    with pytest.raises(TypeError, match="'seed'"):
        vrut.Materials(seed=3)  # a specimen's option, not a material's
