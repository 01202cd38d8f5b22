# SPDX-License-Identifier: MIT
# The Python module's overhead: a loop of 10,000 `analyze(1, dt)` + `nodeDisp(node, 1)` calls in
# Python against the same loop in Tcl (a `for` loop in the module's own interpreter, through
# dabs.tcl), on the same model, built the same way before each run. Runs alternate (Python, Tcl,
# Python, ...) so that both see the same machine load; the medians and their ratio are printed.
# Two models: a linear spring-mass chain (the cheapest step, the worst case for the overhead) and
# the fiber-section portal frame of verification/python/frame.py (a realistic step).
#
#   PYTHONPATH=build/python python3 verification/bench/python-bench.py ?runs? ?steps?
import pathlib
import statistics
import sys
import time

import dabs

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / 'python'))
import frame  # noqa: E402  (the frame model of the compatibility suite)

RUNS = int(sys.argv[1]) if len(sys.argv) > 1 else 7
STEPS = int(sys.argv[2]) if len(sys.argv) > 2 else 10000
DT = 0.001


def chain():
    """Ten masses on linear springs, Newmark, Linear algorithm: a step costs a few microseconds."""
    dabs.wipe()
    dabs.model('basic', '-ndm', 1, '-ndf', 1)
    dabs.node(0, 0.0)
    dabs.fix(0, 1)
    dabs.uniaxialMaterial('Elastic', 1, 1000.0)
    for i in range(1, 11):
        dabs.node(i, float(i), '-mass', 1.0)
        dabs.element('zeroLength', i, i - 1, i, '-mat', 1, '-dir', 1)
    dabs.timeSeries('Sine', 1, 0.0, 1.0e6, 0.5)
    dabs.pattern('UniformExcitation', 1, 1, '-accel', 1)
    dabs.constraints('Plain')
    dabs.numberer('Plain')
    dabs.system('BandGeneral')
    dabs.test('NormDispIncr', 1.0e-10, 10)
    dabs.algorithm('Linear')
    dabs.integrator('Newmark', 0.5, 0.25)
    dabs.analysis('Transient')
    return 10


def portal():
    """The frame of verification/python/frame.py after its gravity and eigen analyses."""
    frame.run(dabs)  # leaves the transient analysis set up at t = 2 s
    return 3


def python_loop(node):
    t0 = time.perf_counter()
    total = 0.0
    for _ in range(STEPS):
        dabs.analyze(1, DT)
        total += dabs.nodeDisp(node, 1)
    return time.perf_counter() - t0, total


def tcl_loop(node):
    dabs.pset('::benchSteps', STEPS)
    dabs.pset('::benchNode', node)
    dabs.pset('::benchDt', DT)
    t0 = time.perf_counter()
    total = float(dabs.tcl('set total 0.0\n'
                           'for {set i 0} {$i < $::benchSteps} {incr i} {\n'
                           '  analyze 1 $::benchDt\n'
                           '  set total [expr {$total + [nodeDisp $::benchNode 1]}]\n'
                           '}\n'
                           'set total'))
    return time.perf_counter() - t0, total


def bench(name, build):
    py, tcl = [], []
    for _ in range(RUNS):
        node = build()
        seconds, total_py = python_loop(node)
        py.append(seconds)
        node = build()
        seconds, total_tcl = tcl_loop(node)
        tcl.append(seconds)
        # Same model, same steps: the same sum of displacements (a check that both loops ran).
        assert abs(total_py - total_tcl) <= 1e-9 * max(1.0, abs(total_tcl)), (total_py, total_tcl)
    p, t = statistics.median(py), statistics.median(tcl)
    print('%-8s %8.1f %8.1f %8.3f %7.2f' % (name, 1e6 * p / STEPS, 1e6 * t / STEPS, p / t,
                                          1e6 * (p - t) / STEPS))
    return p / t


print('%d runs of %d steps (analyze 1 dt + nodeDisp), medians' % (RUNS, STEPS))
print('%-8s %8s %8s %8s %7s' % ('model', 'py us', 'tcl us', 'py/tcl', 'diff us'))
bench('chain', chain)
bench('frame', portal)
