# SPDX-License-Identifier: MIT
# verification/bridge/bridge.py (the case study's pound case from Python, first 7 s of the motion)
# against the same runCase run by the dabs program: the same peaks of every followed quantity,
# to round-off, and the gap history file the plot is drawn from.
import os
import pathlib
import subprocess
import sys

import pytest

BRIDGE = pathlib.Path(__file__).resolve().parent.parent / 'bridge'
DURATION = 7.0


def peaks(text):
    words = text.split()
    return {words[i]: float(words[i + 1]) for i in range(0, len(words), 2)}


def test_bridge_py_matches_the_tcl_run(tmp_path):
    program = os.environ.get('DABS_PROGRAM')
    if not program:
        pytest.skip('DABS_PROGRAM (the dabs program) is not set')
    python = subprocess.run(
        [sys.executable, '-c',
         'import sys, bridge, dabs\n'
         'bridge.main(["--duration", "%g", "--out", sys.argv[1]])\n'
         'print("TAIL", dabs.tcl("set ::tailDuration"))\n'
         'print("PEAKS", dabs.tcl("dict get $::poundResult peak"))' % DURATION, str(tmp_path / 'py')],
        cwd=BRIDGE, capture_output=True, text=True, timeout=300,
        env=dict(os.environ, PYTHONPATH=os.pathsep.join([str(BRIDGE), os.environ['PYTHONPATH']])))
    assert python.returncode == 0, python.stderr
    assert 'completed' in python.stdout
    python_peaks = peaks(python.stdout.split('PEAKS', 1)[1])
    twin = tmp_path / 'twin.tcl'
    twin.write_text('set ::bridgeLibraryOnly 1\n'
                    'source {%s}\n'
                    'set duration %g\n'
                    'set r [runCase pound 1.0 $defaultDt $defaultIntegrator $defaultTol auto]\n'
                    'puts [dict get $r completed]\n'
                    'puts [dict get $r peak]\n' % (BRIDGE / 'bridge.tcl', DURATION))
    tcl = subprocess.run([program, str(twin)], cwd=tmp_path, capture_output=True, text=True,
                         timeout=300)
    assert tcl.returncode == 0, tcl.stderr
    completed, tcl_text = tcl.stdout.split('\n', 1)
    assert completed == '1'
    tcl_peaks = peaks(tcl_text)
    assert python_peaks.keys() == tcl_peaks.keys()
    for key, value in tcl_peaks.items():
        assert python_peaks[key] == pytest.approx(value, rel=1e-12, abs=1e-15), key
    assert min(tcl_peaks['force1'], tcl_peaks['force2']) > 0.0  # both joints pounded
    rows = (tmp_path / 'py' / 'pound.csv').read_text().splitlines()
    # the motion, then bridge.tcl's free vibration before the residuals
    tail = float(python.stdout.split('TAIL', 1)[1].split()[0])
    assert rows[0].startswith('t,gap1x,gap1y') and len(rows) == round((DURATION + tail) / 0.0025) + 1
