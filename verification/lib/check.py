# SPDX-License-Identifier: MIT
"""Checks for the Python verification scripts, printed as check.tcl prints them."""
import sys

failures = 0


def check(ok, what):
    """Prints PASSED or FAILED with `what` and counts the failures."""
    global failures
    print(("PASSED " if ok else "FAILED ") + what)
    if not ok:
        failures += 1


def finish():
    """Exits with 1 when any check failed."""
    sys.exit(1 if failures else 0)
