#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Largest difference between two recorder files of the same script (first column the time),
relative to the scale of the quantity: the largest magnitude over every column of the same
component (columns 2, 2+n, 2+2n, ... for `--components n`), so a nearly zero column, such as the
moment at a pinned end, is judged against that moment elsewhere, not against itself; a component
that is zero in theory is judged against 1e-9 of the file's largest value. Rows are matched by
position.

    compare-results.py a.out b.out ?--components n?  -> largest relative difference and its column
"""
import sys


def read(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.strip():
                rows.append([float(v) for v in line.split()])
    return rows


def compare(a_path, b_path, components=1):
    a, b = read(a_path), read(b_path)
    if len(a) != len(b):
        return float("inf"), f"{len(a)} rows against {len(b)}"
    if any(len(ra) != len(rb) for ra, rb in zip(a, b)):
        return float("inf"), "rows of different lengths"
    worst, where = 0.0, ""
    ncol = len(a[0]) if a else 0
    colmax = [max(abs(r[c]) for r in b) for c in range(ncol)]
    # A component that is zero in theory (torsion of a planar frame: 1e-17 against forces of 1)
    # is judged against round-off of the file's largest value, not against its own noise.
    floor = max(max(colmax[1:], default=0.0) * 1e-9, 1e-300)
    for c in range(ncol):
        same = [c] if c == 0 else range(1 + (c - 1) % components, ncol, components)
        scale = max(max(colmax[k] for k in same), floor)
        d = max(abs(ra[c] - rb[c]) for ra, rb in zip(a, b)) / scale
        if d > worst:
            worst, where = d, f"column {c + 1}"
    return worst, where


if __name__ == "__main__":
    n = int(sys.argv[sys.argv.index("--components") + 1]) if "--components" in sys.argv else 1
    d, where = compare(sys.argv[1], sys.argv[2], n)
    print(f"{d:.3e} {where}")
