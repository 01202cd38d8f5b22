#!/bin/sh
# SPDX-License-Identifier: MIT
# Writes compat-<item>.csv from compat-<item>.tcl with OpenSees: runs the input in a scratch folder
# and keeps the table it wrote. Usage: make-reference.sh path/to/OpenSees compat-<item>.tcl ...
set -e
opensees=$1; shift
here=$(cd "$(dirname "$0")" && pwd)
for input in "$@"; do
  name=$(basename "$input" .tcl)
  scratch=$(mktemp -d)
  (cd "$scratch" && "$opensees" "$here/$name.tcl" > /dev/null 2>&1) || true
  cp "$scratch/$name.out" "$here/$name.csv"
  rm -rf "$scratch"
done
