#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Times dabs against OpenSees on the same Tcl inputs (this folder's models), alternating the two
# programs run by run, and prints per case: the median analysis time of each (the `analyze` call,
# as the scripts print it) and of the whole process, the ratio OpenSees / dabs, dabs' work counts
# (Newton iterations, factorisations, element and fiber-material updates), and the largest
# relative difference between the two programs' recorded results (compare-results.py).
#
#   compare.sh [--opensees PATH] [--dabs PATH] [--repeat N] [--threads N] [--out DIR] [case ...]
#
# Cases: bridge3 bridge10 bridge30 bridge100 rcframe pushover linear-frame linear-frame-once
# (default: all), and bridge1300 (3 steps of 1,300 spans: 46,806 equations, past the 46,340 at
# which a 32-bit row * n + column slot index would overflow; not in the default list).
# OpenSees is looked for at --opensees, then $OPENSEES, then `OpenSees` on the PATH; when it is
# absent the comparison is skipped with a line saying so and dabs is timed alone. OpenSees is
# never built by this project: build it from its public source yourself if you want the ratio.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
dabs="$here/../../../build/dabs"
opensees="${OPENSEES:-}"
repeat=3
threads=1
out="opensees-bench-out"
cases=()
while (($#)); do
  case "$1" in
    --opensees) opensees="$2"; shift 2 ;;
    --dabs) dabs="$2"; shift 2 ;;
    --repeat) repeat="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) cases+=("$1"); shift ;;
  esac
done
((${#cases[@]})) || cases=(bridge3 bridge10 bridge30 bridge100 rcframe pushover linear-frame linear-frame-once)
# case -> script and arguments (OUT: the run's result folder), recorder files with their number of
# components per node or element; findPrograms
source "$here/cases.sh"
findPrograms "timing"

# run PROGRAM DIR SCRIPT ARGS...: prints "analysis_s process_s" and leaves the program's output in DIR/log
run() {
  local prog="$1" dir="$2"; shift 2
  mkdir -p "$dir"
  local t0 t1
  t0=$(date +%s.%N)
  (cd "$dir" && "$prog" "$@" > log 2>&1) || true
  t1=$(date +%s.%N)
  local a
  a=$(grep -o 'analyze_s=[0-9.e+-]*' "$dir/log" | tail -1 | cut -d= -f2)
  echo "${a:-nan} $(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')"
}

printf '| case | dabs analyze s | OpenSees analyze s | OpenSees/dabs | process ratio | largest rel. diff | dabs iterations | factorisations | element updates | material updates |\n'
printf '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n'
for c in "${cases[@]}"; do
  s="$(spec "$c")"
  args="${s%%|*}"; files="${s#*|}"
  script="$here/${args%% *}"; rest="${args#* }"
  da=(); dp=(); oa=(); op=()
  for ((r = 1; r <= repeat; r++)); do
    read -r a p < <(DABS_THREADS="$threads" run "$dabs" "$out/$c/dabs-$r" "$script" ${rest//OUT/$out/$c/dabs-$r/res})
    da+=("$a"); dp+=("$p")
    if [ -n "$opensees" ]; then
      read -r a p < <(run "$opensees" "$out/$c/opensees-$r" "$script" ${rest//OUT/$out/$c/opensees-$r/res})
      oa+=("$a"); op+=("$p")
    fi
  done
  dA=$(printf '%s\n' "${da[@]}" | median); dP=$(printf '%s\n' "${dp[@]}" | median)
  counts=$(grep '^counts' "$out/$c/dabs-1/log" | tail -1 || true)
  get() { echo "$counts" | tr ' ' '\n' | awk -v k="$1" 'prev==k {print; exit} {prev=$0}'; }
  if [ -n "$opensees" ]; then
    oA=$(printf '%s\n' "${oa[@]}" | median); oP=$(printf '%s\n' "${op[@]}" | median)
    worst=0
    for f in $files; do
      name="${f%%:*}"; n="${f##*:}"
      d=$(python3 "$here/compare-results.py" "$out/$c/dabs-1/res/$name" "$out/$c/opensees-1/res/$name" --components "$n" | cut -d' ' -f1)
      worst=$(python3 -c "print(max(float('$worst'), float('$d')))")
    done
    ratio=$(python3 -c "print(f'{$oA/$dA:.2f}')"); pratio=$(python3 -c "print(f'{$oP/$dP:.2f}')")
    oA=$(python3 -c "print(f'{$oA:.4g}')")
    worst=$(python3 -c "print(f'{float(\"$worst\"):.1e}')")
  else
    oA="-"; ratio="-"; pratio="-"; worst="-"
  fi
  # Four significant digits for both programs' times (the pushover's analysis takes about 10 ms).
  printf '| %s | %.4g | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$c" "$dA" "$oA" "$ratio" "$pratio" "$worst" \
    "$(get iterations)" "$(get factorizations)" "$(get elementUpdates)" "$(get materialUpdates)"
done
