"""The Python module's tests: vrut from the build folder (PYTHONPATH), and the
command line it is compared with (VRUT_RUTTING), both set by CTest."""
import os
import shutil

import pytest


@pytest.fixture(scope="session")
def cli():
    exe = os.environ.get("VRUT_RUTTING") or shutil.which("vrut-rutting")
    if not exe:
        pytest.fail("VRUT_RUTTING names no vrut-rutting to compare with (CTest sets it)")
    return exe
