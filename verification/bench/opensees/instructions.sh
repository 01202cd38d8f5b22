#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Counts the instructions dabs and OpenSees execute in their `analyze` commands on the same Tcl
# inputs (this folder's models, shortened so that a run under valgrind takes about a minute), with
# valgrind's callgrind collecting only inside each program's analyze command (dabs' analyzeCmd,
# OpenSees' analyzeModel; every analyze of a script, the gravity analysis included, in both).
# An instruction count is the same from run to run on any machine, so it shows a change of a few
# per cent that the times of compare.sh, which vary by tens of per cent on a shared machine from
# minute to minute, cannot; it is not a time: the two programs do not retire instructions at the
# same rate (dabs' fiber loops hold more divisions and longer dependency chains an instruction,
# OpenSees more calls and copies), so the time ratio of compare.sh and this ratio differ.
# Prints per case: each program's count, OpenSees / dabs, and dabs' count per fiber material
# update (its `counts` line: the updates of all analyses).
#
#   instructions.sh [--opensees PATH] [--dabs PATH] [--out DIR] [case ...]
#
# Cases: bridge3 (400 steps) bridge10 (200) rcframe (300) pushover (140) linear-frame-once (300)
# (default: all). Needs valgrind (Debian package `valgrind`); without OpenSees dabs is counted
# alone.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
dabs="$here/../../../build/dabs"
opensees="${OPENSEES:-}"
out="instructions-out"
cases=()
while (($#)); do
  case "$1" in
    --opensees) opensees="$2"; shift 2 ;;
    --dabs) dabs="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    -h|--help) sed -n '2,19p' "$0"; exit 0 ;;
    *) cases+=("$1"); shift ;;
  esac
done
((${#cases[@]})) || cases=(bridge3 bridge10 rcframe pushover linear-frame-once)
command -v valgrind > /dev/null || { echo "valgrind not found (apt-get install valgrind)"; exit 2; }
source "$here/cases.sh"  # findPrograms
findPrograms "counting"

# case -> script and arguments (OUT: the run's result folder)
short() {
  case "$1" in
    bridge3) echo "bridge.tcl 3 400 OUT" ;;
    bridge10) echo "bridge.tcl 10 200 OUT" ;;
    rcframe) echo "rcframe.tcl 300 OUT" ;;
    pushover) echo "pushover.tcl 140 OUT" ;;
    linear-frame-once) echo "linear-frame.tcl 300 OUT -factorOnce" ;;
    *) echo "unknown case $1" >&2; exit 2 ;;
  esac
}

# count PROGRAM FUNCTION DIR SCRIPT ARGS...: prints the instructions callgrind collected inside
# FUNCTION (a callgrind --toggle-collect pattern) and leaves the program's output in DIR/log
count() {
  local prog="$1" fn="$2" dir="$3"; shift 3
  mkdir -p "$dir"
  (cd "$dir" && DABS_THREADS=1 valgrind --tool=callgrind --toggle-collect="$fn" \
    --callgrind-out-file="$dir/callgrind.out" "$prog" "$@" > log 2> valgrind.log) || true
  grep -o 'Collected : [0-9]*' "$dir/valgrind.log" | awk '{print $3}' | tail -1
}

printf '| case | dabs instructions | OpenSees instructions | OpenSees/dabs | dabs per material update |\n'
printf '|---|---:|---:|---:|---:|\n'
for c in "${cases[@]}"; do
  args="$(short "$c")"
  script="$here/${args%% *}"; rest="${args#* }"
  d=$(count "$dabs" 'dabs::tcl::(anonymous namespace)::analyzeCmd*' "$out/$c/dabs" \
    "$script" ${rest//OUT/$out/$c/dabs/res})
  updates=$(grep '^counts' "$out/$c/dabs/log" | tail -1 | tr ' ' '\n' |
    awk 'prev=="materialUpdates" {print; exit} {prev=$0}')
  perUpdate=$(python3 -c "u=int('${updates:-0}'); print(f'{$d/u:.0f}' if u else '-')")
  if [ -n "$opensees" ]; then
    o=$(count "$opensees" 'analyzeModel*' "$out/$c/opensees" "$script" \
      ${rest//OUT/$out/$c/opensees/res})
    ratio=$(python3 -c "print(f'{$o/$d:.2f}')")
  else
    o="-"; ratio="-"
  fi
  printf '| %s | %s | %s | %s | %s |\n' "$c" "$d" "$o" "$ratio" "$perUpdate"
done
