# SPDX-License-Identifier: MIT
# Shared fixtures of the Python module's tests (run by ctest `python.module` with PYTHONPATH set to
# <build>/python and DABS_PROGRAM to the dabs program).
import os
import subprocess

import pytest

import dabs


@pytest.fixture(autouse=True)
def fresh_model():
    """Every test starts from an empty model."""
    dabs.wipe()
    yield
    dabs.wipe()


def run_program(script, tmp_path):
    """Runs a Tcl script with the dabs program (not the module) and returns its standard output."""
    program = os.environ.get('DABS_PROGRAM')
    if not program:
        pytest.skip('DABS_PROGRAM (the dabs program to run the Tcl twin) is not set')
    path = tmp_path / 'twin.tcl'
    path.write_text(script)
    done = subprocess.run([program, str(path)], cwd=tmp_path, capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    return done.stdout
