#!/bin/sh
# SPDX-License-Identifier: MIT
# Writes compat-<item>.csv from compat-<item>.tcl with OpenSees: runs the input in a scratch folder
# and keeps the table it wrote. Usage: make-reference.sh path/to/OpenSees compat-<item>.tcl ...
# An input that uses a DABS element has an OpenSees twin, opensees-twins/<item>.tcl, which writes
# the same table with OpenSees' element; OpenSees runs the twin when there is one.
set -e
opensees=$1; shift
here=$(cd "$(dirname "$0")" && pwd)
for input in "$@"; do
  name=$(basename "$input" .tcl)
  scratch=$(mktemp -d)
  script="$here/$name.tcl"
  [ -f "$here/opensees-twins/$name.tcl" ] && script="$here/opensees-twins/$name.tcl"
  (cd "$scratch" && "$opensees" "$script" > /dev/null 2>&1) || true
  cp "$scratch/$name.out" "$here/$name.csv"
  rm -rf "$scratch"
done
