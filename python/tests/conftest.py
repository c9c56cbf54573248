"""The Python module's tests: vrut from the build folder (PYTHONPATH), and the
command line it is compared with (VRUT_RUTTING), both set by CTest."""
import json
import os
import pathlib
import shutil

import jsonschema
import pytest

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
