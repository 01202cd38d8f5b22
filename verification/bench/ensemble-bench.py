#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Speed-up of the `ensemble run` job farm on 2 processes against 1.

Usage: ensemble-bench.py path/to/build [repeat] [lengthFactor] [mpirun options...]
       (mpirun options by default: --oversubscribe --bind-to none, for Open MPI)

Runs the 16 jobs of verification/ensemble/jobs.tcl (yielding oscillators, run lengths 1 to 10 in
an order that mixes long and short; all 16 complete) `repeat` times (default 3) with the serial
program and with `mpirun -n 2 dabs-mp`, alternating, and prints the wall time of the ensemble as
the script measures it (from the call of `ensemble run` to its return, so the same span in both),
the wall time of the whole command (with the start of Open MPI), and the speed-ups. lengthFactor
(default 4500) scales the jobs: about 0.5 to 5 s each on one core of the reference machine.

The reference for the speed-up is what these job lengths allow: with jobs handed out in order to
whichever process is free, the makespan on 2 processes is that of greedy list scheduling of the
serial run's job times (computed below); it is above half the serial time when the last long job
starts late.
"""
import csv
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
JOBS = os.path.join(HERE, "..", "ensemble", "jobs.tcl")


def cpu_of_children():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run(cmd, out):
    shutil.rmtree(out, ignore_errors=True)
    start = time.monotonic()
    cpu = cpu_of_children()
    result = subprocess.run(cmd, capture_output=True, text=True, check=True)
    total = time.monotonic() - start
    run.cpu = cpu_of_children() - cpu
    ensemble = next(float(line.split()[1]) for line in result.stdout.splitlines()
                    if line.startswith("wall "))
    with open(os.path.join(out, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    return ensemble, total, rows


def list_schedule(times, processes):
    """Makespan of handing jobs out in order to whichever process is free first."""
    free = [0.0] * processes
    for t in times:
        i = free.index(min(free))
        free[i] += t
    return max(free)


def main():
    build = os.path.abspath(sys.argv[1])
    repeat = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    factor = sys.argv[3] if len(sys.argv) > 3 else "4500"
    options = sys.argv[4:] or ["--oversubscribe", "--bind-to", "none"]
    env_note = os.uname()
    tmp = tempfile.mkdtemp(prefix="dabs-ensemble-bench-")
    serial, parallel, bounds, loads = [], [], [], []
    try:
        for k in range(repeat):
            loads.append(os.getloadavg()[0])
            s = run([os.path.join(build, "dabs"), JOBS, os.path.join(tmp, "s"), "16", "", factor, "0"],
                    os.path.join(tmp, "s"))
            s_cpu = run.cpu
            p = run(["mpirun", "-n", "2", *options, os.path.join(build, "dabs-mp"), JOBS,
                     os.path.join(tmp, "p"), "16", "", factor, "0"], os.path.join(tmp, "p"))
            p_cpu = run.cpu
            # Share of the ensemble's wall time each process spent in jobs: what the farm leaves
            # idle, whatever share of a core the machine gives each process.
            busy = {}
            for r in p[2]:
                busy[r["rank"]] = busy.get(r["rank"], 0.0) + float(r["seconds"]) / p[0]
            times = [float(r["seconds"]) for r in s[2]]
            bound = sum(times) / list_schedule(times, 2)
            serial.append(s)
            parallel.append(p)
            bounds.append(bound)
            ranks = sorted({r["rank"] for r in p[2]})
            print(f"run {k + 1}: 1 process {s[0]:.2f} s (command {s[1]:.2f} s), 2 processes "
                  f"{p[0]:.2f} s (command {p[1]:.2f} s, ranks {','.join(ranks)}): speed-up "
                  f"{s[0] / p[0]:.2f} (command {s[1] / p[1]:.2f}); list-scheduling bound {bound:.2f}; "
                  f"jobs {min(times):.2f} to {max(times):.2f} s; load average before {loads[-1]:.2f}; "
                  f"CPU s {s_cpu:.1f} and {p_cpu:.1f}; busy "
                  + ", ".join(f"rank {k} {v:.0%}" for k, v in sorted(busy.items())),
                  flush=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    ms = statistics.median(x[0] for x in serial)
    mp = statistics.median(x[0] for x in parallel)
    print(f"median: 1 process {ms:.2f} s, 2 processes {mp:.2f} s, speed-up {ms / mp:.2f} "
          f"(bound {statistics.median(bounds):.2f}); whole commands "
          f"{statistics.median(x[1] for x in serial):.2f} s and "
          f"{statistics.median(x[1] for x in parallel):.2f} s; machine {env_note.nodename} "
          f"{os.cpu_count()} cores, load average {statistics.median(loads):.2f}")


if __name__ == "__main__":
    main()
