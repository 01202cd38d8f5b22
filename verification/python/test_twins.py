# SPDX-License-Identifier: MIT
# Each script here (frame, truss, contact, yoshida) run through the Python module must print what
# its Tcl twin prints when the dabs program runs it, to round-off; frame and truss must also give
# the numbers OpenSeesPy gave for the same script (reference/*-openseespy.csv, see README.md).
# Run by ctest `verify.python.twins` with PYTHONPATH=<build>/python and DABS_PROGRAM set.
import importlib
import os
import pathlib
import subprocess
import sys

import pytest

import dabs

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
SCRIPTS = sorted(p.stem for p in HERE.glob('*.py')
                 if p.with_suffix('.tcl').exists() and not p.stem.startswith('test_'))
ROUND_OFF = 1e-12  # relative to the largest value of the row
# OpenSees' solvers and element loops order some sums differently: the same equations solved to
# the test tolerances of the scripts (1e-10 to 1e-12) agree to this, relative to the row.
OPENSEES = 1e-9


def parse(text, sep=None):
    rows = []
    for line in text.splitlines():
        if not line.strip() or line.startswith('#'):
            continue
        words = line.split(sep)
        rows.append([words[0]] + [float(w) for w in words[1:]])
    return rows


def python_rows(script):
    rows = importlib.import_module(script).run(dabs)
    return [[r[0]] + [float(v) for v in r[1:]] for r in rows]


def assert_rows_equal(got, expected, tolerance):
    assert [r[0] for r in got] == [r[0] for r in expected]
    for g, e in zip(got, expected):
        assert len(g) == len(e), g[0]
        scale = max([abs(v) for v in e[1:]] + [1e-300])
        for a, b in zip(g[1:], e[1:]):
            assert abs(a - b) <= tolerance * scale, (g, e)


@pytest.mark.parametrize('script', SCRIPTS)
def test_python_script_matches_its_tcl_twin(script, tmp_path):
    program = os.environ.get('DABS_PROGRAM')
    if not program:
        pytest.skip('DABS_PROGRAM (the dabs program) is not set')
    done = subprocess.run([program, str(HERE / (script + '.tcl'))], cwd=tmp_path,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    tcl = parse(done.stdout)
    assert len(tcl) > 3 and not any(r[0] == 'failed' for r in tcl)
    assert_rows_equal(python_rows(script), tcl, ROUND_OFF)


@pytest.mark.parametrize('script', [p.name.split('-openseespy')[0]
                                    for p in sorted((HERE / 'reference').glob('*-openseespy.csv'))])
def test_python_script_matches_openseespy(script):
    reference = parse((HERE / 'reference' / (script + '-openseespy.csv')).read_text(), ',')
    assert_rows_equal(python_rows(script), reference, OPENSEES)


def test_return_types_are_openseespy_types():
    import return_types
    expected = [line.split(': ', 1) for line in
                (HERE / 'reference' / 'return-types-openseespy.txt').read_text().splitlines()
                if line and not line.startswith('#')]
    assert [list(t) for t in return_types.types(dabs)] == expected
