#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Recorders keep every committed step when dabs is killed in the middle of `analyze 20000`.

Usage: kill_test.py path/to/dabs

For SIGTERM, SIGINT and SIGHUP the program stops after the step in progress, closes its recorders
and exits with status 128 + signal; every recorder then holds the same number K of complete rows,
at times dt, 2 dt, ..., K dt, and the last row equals the one a fresh run of `analyze K` records.
For SIGKILL nothing can run at the kill: the rows of every committed step are there already, and
the two row recorders differ by at most the step in progress.
"""
import os
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from check import check, finish  # noqa: E402

DABS = os.path.abspath(sys.argv[1])
DT = 0.001


# A 2D cantilever of 200 elastic beams shaken at its base: about a millisecond per step, so
# `analyze 20000` runs long enough to be killed in the middle.
MODEL = """
model basic -ndm 2 -ndf 3
set n 200
for {set i 0} {$i <= $n} {incr i} { node [expr {$i + 1}] 0.0 [expr {0.1 * $i}] -mass 1.0 1.0 0.01 }
fix 1 1 1 1
geomTransf Linear 1
for {set i 1} {$i <= $n} {incr i} { element elasticBeamColumn $i $i [expr {$i + 1}] 0.01 2.0e8 1.0e-4 1 }
timeSeries Trig 1 0.0 1000.0 0.5 -factor 1.0
pattern UniformExcitation 1 1 -accel 1
recorder Node -file disp.out -time -node 51 101 201 -dof 1 2 disp
recorder Element -file force.out -time -ele 1 2 force
recorder EnvelopeNode -file envelope.out -node 201 -dof 1 disp
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1e-10 20
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
"""


def rows(path):
    with open(path, "rb") as f:
        data = f.read()
    complete = data.endswith(b"\n") or not data
    lines = data.decode().splitlines()
    return lines, complete


def times_consecutive(lines):
    for k, line in enumerate(lines, start=1):
        if abs(float(line.split()[0]) - k * DT) > 1e-9:
            return False
    return True


def fresh_last_row(steps):
    with tempfile.TemporaryDirectory() as d:
        subprocess.run([DABS], input=(MODEL + f"analyze {steps} {DT}\n").encode(), cwd=d, check=True,
                       capture_output=True, timeout=600)
        return rows(os.path.join(d, "disp.out"))[0][-1]


def kill_run(sig):
    name = signal.Signals(sig).name
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "run.tcl"), "w") as f:
            f.write(MODEL + f"analyze 20000 {DT}\nputs finished\n")
        p = subprocess.Popen([DABS, "run.tcl"], cwd=d, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        disp = os.path.join(d, "disp.out")
        # Kill once a few hundred steps are committed.
        end = time.time() + 120
        while time.time() < end and p.poll() is None:
            if os.path.exists(disp) and os.path.getsize(disp) > 300 * 40:
                break
            time.sleep(0.02)
        running = p.poll() is None
        check(running, f"{name}: the run is still going when the signal is sent")
        p.send_signal(sig)
        out, _ = p.communicate(timeout=120)
        code = p.returncode
        expected = -sig if sig == signal.SIGKILL else 128 + sig
        check(code == expected, f"{name}: exit status {code} (expected {expected})")
        check(b"finished" not in out, f"{name}: the analysis did not run to its end")
        d_lines, d_complete = rows(disp)
        f_lines, f_complete = rows(os.path.join(d, "force.out"))
        e_lines, _ = rows(os.path.join(d, "envelope.out"))
        k = len(d_lines)
        check(k > 100 and d_complete and f_complete,
              f"{name}: {k} displacement and {len(f_lines)} force rows, every row complete")
        check(times_consecutive(d_lines) and times_consecutive(f_lines),
              f"{name}: rows at dt, 2 dt, ... with no step missing")
        if sig == signal.SIGKILL:
            check(abs(len(f_lines) - k) <= 1, f"{name}: the recorders differ by at most the step in progress")
            steps = min(k, len(f_lines))
        else:
            check(len(f_lines) == k, f"{name}: both row recorders end at the same committed step")
            check(len(e_lines) == 3, f"{name}: the envelope recorder holds its three rows")
            steps = k
        check(fresh_last_row(steps) == d_lines[steps - 1],
              f"{name}: row {steps} equals the last row of a fresh `analyze {steps}`")


for s in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP, signal.SIGKILL):
    kill_run(s)
finish()
