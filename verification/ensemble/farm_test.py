#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The `ensemble run` job farm: results, failures, and a run killed midway then rerun.

Usage: farm_test.py path/to/dabs [mpirun path/to/dabs-mp [mpirun options...]]

With the serial program alone: the ensemble of jobs.tcl (16 oscillators, one analysis that fails,
one command that raises an error) records every job, the failed one with its analysis code and
the erroneous one with its message, and the others complete; a rerun runs nothing; a run killed
with SIGKILL after a few jobs leaves only whole result files, and the rerun runs exactly the jobs
without a result and ends with the same merged results.

With mpirun and dabs-mp as well: the same under `mpirun -n 2`, and every job's result equals the
serial run's bit for bit (the columns of the analysis; `rank` and `seconds` say where and how long).
"""
import csv
import glob
import io
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from check import check, finish  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
JOBS = os.path.join(HERE, "jobs.tcl")
COUNT = 16
# Steps scale: jobs of about 0.04 to 0.4 s on one core, so that a kill lands in the middle of the
# ensemble.
KILL_LENGTH = 400
# Columns that say where and how long a job ran, not what it computed.
PLACE_COLUMNS = ("rank", "seconds")


def command(program, out, log="", length=1, progress=0):
    args = [JOBS, out, str(COUNT), log, str(length), "1", str(progress)]
    if program["mpirun"]:
        return [program["mpirun"], "-n", "2", *program["options"], program["dabs"], *args]
    return [program["dabs"], *args]


def run(program, out, log="", length=1, progress=0):
    result = subprocess.run(command(program, out, log, length, progress), capture_output=True,
                            text=True, timeout=600)
    if result.returncode != 0:
        print(result.stdout, result.stderr)
    return result


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def analysis_columns(row):
    return {k: v for k, v in row.items() if k not in PLACE_COLUMNS}


def job_file_is_whole(path):
    """A job's file: a header and one row with as many fields, ending in a line break."""
    with open(path, newline="") as f:
        text = f.read()
    rows = list(csv.reader(io.StringIO(text)))
    return text.endswith("\n") and len(rows) == 2 and len(rows[0]) == len(rows[1])


def log_ids(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [line.split()[0] for line in f if line.strip()]


def log_pids(path):
    if not os.path.exists(path):
        return set()
    with open(path) as f:
        return {int(line.split()[2]) for line in f if len(line.split()) == 3}


def check_results(name, rows):
    by_id = {r["job"]: r for r in rows}
    check(len(rows) == COUNT and len(by_id) == COUNT, f"{name}: merged CSV has the {COUNT} jobs "
          f"(got {len(rows)})")
    failed = by_id.get("osc05", {})
    check(failed.get("status") == "failed" and failed.get("code") not in ("", "0", None),
          f"{name}: the diverging analysis is recorded as failed with its code "
          f"({failed.get('status')}, code {failed.get('code')})")
    error = by_id.get("osc09", {})
    check(error.get("status") == "error" and "no such material" in error.get("error", ""),
          f"{name}: the job raising an error is recorded with its message ({error.get('error')})")
    others = [r for r in rows if r["job"] not in ("osc05", "osc09")]
    check(all(r["status"] == "ok" and r["code"] == "0" and r["peak"] != "" for r in others),
          f"{name}: the other {COUNT - 2} jobs complete after the failing ones")


def kill_and_rerun(name, program, reference, tmp):
    out = os.path.join(tmp, name + "-killed")
    log = os.path.join(tmp, name + "-killed.log")
    proc = subprocess.Popen(command(program, out, log, KILL_LENGTH), stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    deadline = time.time() + 300
    while time.time() < deadline and proc.poll() is None:
        if len(glob.glob(os.path.join(out, "jobs", "*.csv"))) >= 4:
            break
        time.sleep(0.01)
    still_running = proc.poll() is None
    if still_running:
        os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    # mpirun puts its processes in their own process groups; kill each one the log names (a batch
    # system ending a job kills them all the same way), and wait until they are gone.
    for pid in log_pids(log):
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    for pid in log_pids(log):
        while os.path.exists(f"/proc/{pid}") and time.time() < deadline:
            time.sleep(0.01)
    check(still_running, f"{name}: the run was killed midway")
    done = sorted(os.path.basename(p)[:-4] for p in glob.glob(os.path.join(out, "jobs", "*.csv")))
    check(0 < len(done) < COUNT, f"{name}: {len(done)} of {COUNT} results written before the kill")
    check(all(job_file_is_whole(p) for p in glob.glob(os.path.join(out, "jobs", "*.csv"))),
          f"{name}: every result file left by the kill is whole")
    # Jobs recorded as failed or ok are done; a job that raised an error is run again.
    finished = [j for j in done
                if read_csv(os.path.join(out, "jobs", j + ".csv"))[0]["status"] in ("ok", "failed")]
    os.remove(log)
    result = run(program, out, log, KILL_LENGTH)
    check(result.returncode == 0, f"{name}: the rerun completes (status {result.returncode})")
    rerun = log_ids(log)
    check(not set(rerun) & set(finished),
          f"{name}: the rerun redoes none of the {len(finished)} finished jobs "
          f"(ran {len(rerun)}: {' '.join(sorted(rerun))})")
    check(len(rerun) == COUNT - len(finished) and len(set(rerun)) == len(rerun),
          f"{name}: the rerun runs each of the other {COUNT - len(finished)} jobs once")
    rows = read_csv(os.path.join(out, "results.csv"))
    check_results(name + " after kill and rerun", rows)
    same = [analysis_columns(r) for r in rows] == [analysis_columns(r) for r in reference]
    check(same, f"{name}: results after kill and rerun equal an uninterrupted serial run")


def main():
    dabs = os.path.abspath(sys.argv[1])
    serial = {"dabs": dabs, "mpirun": None, "options": []}
    parallel = None
    if len(sys.argv) > 3:
        parallel = {"dabs": os.path.abspath(sys.argv[3]), "mpirun": sys.argv[2],
                    "options": sys.argv[4:]}
    tmp = tempfile.mkdtemp(prefix="dabs-farm-")
    try:
        out = os.path.join(tmp, "serial")
        log = os.path.join(tmp, "serial.log")
        result = run(serial, out, log)
        check(result.returncode == 0, f"serial: ensemble completes (status {result.returncode})")
        check("ensemble:" not in result.stderr,
              "serial: no progress lines when stderr is not a terminal and -progress is not given")
        reference = read_csv(os.path.join(out, "results.csv"))
        check_results("serial", reference)
        check(sorted(log_ids(log)) == [f"osc{i:02d}" for i in range(1, COUNT + 1)],
              "serial: one process ran every job once")
        os.remove(log)
        result = run(serial, out, log)
        rerun = log_ids(log)
        check(result.returncode == 0 and rerun == ["osc09"],
              f"serial: a rerun runs only the job that raised an error (ran {rerun})")
        check(f"skipped {COUNT - 1}" in result.stdout, "serial: the rerun reports 15 skipped jobs")
        # Reference for the comparisons: long jobs, uninterrupted, one process.
        long_out = os.path.join(tmp, "serial-long")
        run(serial, long_out, "", KILL_LENGTH)
        long_reference = read_csv(os.path.join(long_out, "results.csv"))

        # -progress: a line per finished job on stderr, the count, failures and errors so far.
        progress_out = os.path.join(tmp, "serial-progress")
        result = run(serial, progress_out, "", 1, 1)
        lines = [l for l in result.stderr.splitlines() if l.startswith("ensemble: ")]
        check(len(lines) == COUNT, f"-progress: one line per job ({len(lines)} of {COUNT})")
        check(bool(lines) and lines[-1].startswith(
            f"ensemble: {COUNT}/{COUNT} done, 1 failed, 1 errors, "),
              f"-progress: the last line counts every job, the failure and the error "
              f"({lines[-1] if lines else ''!r})")
        check(all(" elapsed, about " in l and " left (osc" in l for l in lines),
              "-progress: each line has the time elapsed, the time left and the job")
        check([analysis_columns(r) for r in read_csv(os.path.join(progress_out, "results.csv"))]
              == [analysis_columns(r) for r in reference],
              "-progress: the results are those of the run without it")

        if parallel is None:
            kill_and_rerun("serial", serial, long_reference, tmp)
        else:
            out = os.path.join(tmp, "mpi")
            log = os.path.join(tmp, "mpi.log")
            result = run(parallel, out, log)
            check(result.returncode == 0, f"mpirun -n 2: ensemble completes (status {result.returncode})")
            rows = read_csv(os.path.join(out, "results.csv"))
            check_results("mpirun -n 2", rows)
            ranks = {r["rank"] for r in rows}
            check(ranks == {"0", "1"}, f"mpirun -n 2: both processes ran jobs (ranks {sorted(ranks)})")
            check(sorted(log_ids(log)) == [f"osc{i:02d}" for i in range(1, COUNT + 1)],
                  "mpirun -n 2: every job ran once")
            same = [analysis_columns(r) for r in rows] == [analysis_columns(r) for r in reference]
            check(same, "mpirun -n 2: every job's results equal the serial run's bit for bit")
            for r, s in zip(rows, reference):
                if analysis_columns(r) != analysis_columns(s):
                    print("  differs:", r, s)
            serial_files = sorted(glob.glob(os.path.join(tmp, "serial", "jobs", "*.csv")))
            check(len(serial_files) == COUNT, "serial: one result file per job")
            kill_and_rerun("mpirun -n 2", parallel, long_reference, tmp)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
