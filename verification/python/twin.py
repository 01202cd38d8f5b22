# SPDX-License-Identifier: MIT
"""What the compatibility scripts share: print a script's rows as its Tcl twin prints them.

Each script here defines run(ops) -> rows (lists of a label and numbers) and ends with
`main(run)`, so that `python3 script.py` prints the rows with dabs, and the tests and
make-reference.py call run() with dabs or with OpenSeesPy.
"""
import sys


def show(rows):
    """One line a row; floats as repr (every digit), the rest as str."""
    for row in rows:
        print(' '.join(repr(v) if isinstance(v, float) else str(v) for v in row))


def main(run):
    import dabs
    show(run(dabs))
    sys.stdout.flush()
