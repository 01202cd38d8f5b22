#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The options a newcomer tries first: --help, -h, --version, and an unknown option.

Usage: options_test.py path/to/program version

The program (dabs or dabs-mp) runs with each option, standard input from /dev/null and a time
limit (an option that opened the shell would wait for input): --help and -h print the same
usage (the ways to run it, DABS_THREADS, where the documentation is) and exit 0; --version
prints the program's name and the project version given on the command line (CMake's), a
commit, the compiler and the optional parts, and exits 0; an unknown option starting with --
exits 2 with a message naming it and pointing to --help. `analyze n dt -progress` reports on
stderr, and nothing without it.
"""
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from check import check, finish  # noqa: E402

PROGRAM = os.path.abspath(sys.argv[1])
VERSION = sys.argv[2]
NAME = os.path.basename(PROGRAM)


def run(*args):
    return subprocess.run([PROGRAM, *args], stdin=subprocess.DEVNULL, capture_output=True,
                          text=True, timeout=30)


help_long = run("--help")
help_short = run("-h")
check(help_long.returncode == 0, f"{NAME} --help exits 0 (got {help_long.returncode})")
check(help_long.stdout == help_short.stdout and help_short.returncode == 0,
      f"{NAME} -h prints what --help prints")
for needle in ("Usage:", f"{NAME} script.tcl ?args...?", "--version", "DABS_THREADS",
               "README.md"):
    check(needle in help_long.stdout, f"--help names {needle!r}")

version = run("--version")
lines = version.stdout.splitlines()
check(version.returncode == 0, f"{NAME} --version exits 0 (got {version.returncode})")
check(bool(lines) and lines[0] == f"{NAME} {VERSION}",
      f"--version's first line is '{NAME} {VERSION}' (got {lines[0] if lines else ''!r})")
fields = dict(line.split(":", 1) for line in lines[1:] if ":" in line)
commit = fields.get("commit", "").strip()
check(re.fullmatch(r"[0-9a-f]{12}", commit) is not None or commit.startswith("unknown"),
      f"--version gives the commit (12 hex digits or 'unknown ...'; got {commit!r})")
for part in ("compiler", "Tcl", "MPI", "NLopt", "viewer", "Python"):
    check(fields.get(part, "").strip() != "", f"--version reports {part}")

# analyze -progress: a line on stderr (here not a terminal: whole lines), the last one complete.
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "progress-model.tcl")
with_progress = subprocess.run([PROGRAM, script, "-progress"], stdin=subprocess.DEVNULL,
                               capture_output=True, text=True, timeout=60)
lines = [l for l in with_progress.stderr.splitlines() if l.startswith("analyze: ")]
check(with_progress.returncode == 0 and with_progress.stdout.strip() == "0",
      f"analyze -progress completes and returns 0 (got {with_progress.stdout.strip()!r})")
check(bool(lines) and lines[-1].startswith("analyze: 2000/2000 steps (100 %), t = 2,"),
      f"analyze -progress ends with the whole count and time ({lines[-1] if lines else ''!r})")
without = subprocess.run([PROGRAM, script], stdin=subprocess.DEVNULL, capture_output=True,
                         text=True, timeout=60)
check("analyze:" not in without.stderr, "without -progress analyze prints nothing on stderr")

unknown = run("--frobnicate")
check(unknown.returncode == 2, f"an unknown option exits 2 (got {unknown.returncode})")
check("--frobnicate" in unknown.stderr and "--help" in unknown.stderr,
      f"its message names the option and --help (got {unknown.stderr.strip()!r})")
check(unknown.stdout == "", "and prints nothing on stdout")
finish()
