#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The automatic thread choice (`threads auto`, the default; tcl/analysis/driver/ThreadChoice.h)
# against one and two threads on the models of opensees/compare.sh: each case run with
# DABS_THREADS=1, 2 and auto in turn (the order rotated from repeat to repeat), the medians of the
# analyze time the scripts print, the speed-ups over one thread, the count auto chose and the
# ratio it measured (analysisStatistics), and whether every recorder file is the same byte for
# byte as one thread's (results do not depend on the thread count).
#
#   threads.sh [--dabs PATH] [--repeat N] [--out DIR] [case ...]   (default: every case, 3 repeats)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
dabs="$here/../../build/dabs"
repeat=3
out="threads-bench-out"
cases=()
while (($#)); do
  case "$1" in
    --dabs) dabs="$2"; shift 2 ;;
    --repeat) repeat="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) cases+=("$1"); shift ;;
  esac
done
((${#cases[@]})) || cases=(bridge3 bridge10 bridge30 bridge100 rcframe pushover linear-frame-once)
[ -x "$dabs" ] || { echo "dabs not found at $dabs (--dabs PATH)"; exit 2; }
mkdir -p "$out"
out="$(cd "$out" && pwd)"

source "$here/opensees/cases.sh"

printf '| case | 1 thread, analyze s | 2 threads: speed-up | auto: speed-up | auto chose | measured ratio | same results |\n'
printf '|---|---:|---:|---:|---:|---:|---|\n'
for c in "${cases[@]}"; do
  s="$(spec "$c")"
  args="${s%%|*}"
  script="$here/opensees/${args%% *}"; rest="${args#* }"
  declare -A times=([1]="" [2]="" [auto]="")
  orders=("1 2 auto" "2 auto 1" "auto 1 2")
  for ((r = 1; r <= repeat; r++)); do
    for t in ${orders[$(((r - 1) % 3))]}; do
      dir="$out/$c/$t-$r"
      mkdir -p "$dir"
      (cd "$dir" && DABS_THREADS="$t" "$dabs" "$script" ${rest//OUT/$dir/res} > log 2>&1) || true
      a=$(grep -o 'analyze_s=[0-9.e+-]*' "$dir/log" | tail -1 | cut -d= -f2)
      times[$t]+="${a:-nan} "
    done
  done
  one=$(printf '%s\n' ${times[1]} | median)
  two=$(printf '%s\n' ${times[2]} | median)
  auto=$(printf '%s\n' ${times[auto]} | median)
  counts=$(grep '^counts' "$out/$c/auto-1/log" | tail -1 || true)
  get() { echo "$counts" | tr ' ' '\n' | awk -v k="$1" 'prev==k {print; exit} {prev=$0}'; }
  same=yes
  for f in "$out/$c/1-1/res/"*; do
    for t in 2 auto; do cmp -s "$f" "$out/$c/$t-1/res/$(basename "$f")" || same=no; done
  done
  printf '| %s | %.3f | %.2f | %.2f | %s | %s | %s |\n' "$c" "$one" \
    "$(python3 -c "print($one/$two)")" "$(python3 -c "print($one/$auto)")" \
    "$(get threads)" "$(get threadRatio)" "$same"
done
