"""The Python module's tests: vrut from the build folder (PYTHONPATH), and the
command line it is compared with (VRUT_RUTTING), both set by CTest."""
import json
import os
import pathlib
import shutil

import jsonschema
import pytest

# A tiny 2D run (60 x 30 mm of 1 mm disks, a short settling, a large time
# shift: about 0.15 s) for the tests that compare two runs with each other
# and need no physics of the full test.
TINY = dict(gradation=2, seed=1, width_mm=60, height_mm=30, disk_radius_mm=1, shift=1e5, settle_steps=300, threads=1)


def as_args(options):
    """The command line's arguments for the module's keywords."""
    return [a for k, v in options.items() for a in ("--" + k.replace("_", "-"), str(v))]


# summary.json's one shape, 2D and 3D (docs/summary.schema.json).
SUMMARY_SCHEMA = json.loads((pathlib.Path(__file__).parents[2] / "docs" / "summary.schema.json").read_text())
jsonschema.Draft202012Validator.check_schema(SUMMARY_SCHEMA)


def check_summary(summary):
    """Fails with every place where summary departs from the schema."""
    errors = sorted(jsonschema.Draft202012Validator(SUMMARY_SCHEMA).iter_errors(summary), key=str)
    assert not errors, "\n".join(f"{list(e.absolute_path)}: {e.message}" for e in errors)


@pytest.fixture(scope="session")
def cli():
    exe = os.environ.get("VRUT_RUTTING") or shutil.which("vrut-rutting")
    if not exe:
        pytest.fail("VRUT_RUTTING names no vrut-rutting to compare with (CTest sets it)")
    return exe
