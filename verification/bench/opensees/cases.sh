# SPDX-License-Identifier: MIT
# The benchmark models of this folder, shared by compare.sh, instructions.sh and ../threads.sh
# (sourced): spec CASE prints "script args|recorder files with their component counts" (OUT stands
# for the results folder); median reads numbers, one a line, and prints their median;
# findPrograms WHAT checks the programs and the output folder of compare.sh and instructions.sh.
spec() {
  case "$1" in
    bridge3) echo "bridge.tcl 3 4000 OUT|girder-disp.out:2 pier-disp.out:2 pier-force.out:6" ;;
    bridge10) echo "bridge.tcl 10 1000 OUT|girder-disp.out:2 pier-disp.out:2 pier-force.out:6" ;;
    bridge30) echo "bridge.tcl 30 1000 OUT|girder-disp.out:2 pier-disp.out:2 pier-force.out:6" ;;
    bridge100) echo "bridge.tcl 100 200 OUT|girder-disp.out:2 pier-disp.out:2 pier-force.out:6" ;;
    bridge1300) echo "bridge.tcl 1300 3 OUT|girder-disp.out:2 pier-disp.out:2 pier-force.out:6" ;;
    rcframe) echo "rcframe.tcl 1500 OUT|disp.out:1 force.out:3" ;;
    pushover) echo "pushover.tcl 140 OUT|tip.out:1 force.out:6" ;;
    linear-frame) echo "linear-frame.tcl 1500 OUT|roof.out:2 base.out:6" ;;
    linear-frame-once) echo "linear-frame.tcl 1500 OUT -factorOnce|roof.out:2 base.out:6" ;;
    *) echo "unknown case $1" >&2; exit 2 ;;
  esac
}

median() { sort -g | awk '{v[NR]=$1} END {if (NR%2) print v[(NR+1)/2]; else print (v[NR/2]+v[NR/2+1])/2}'; }

# findPrograms WHAT: $opensees becomes the OpenSees given (--opensees, else $OPENSEES), else
# `OpenSees` on the PATH, else "" with a line saying dabs is WHAT alone; exits when $dabs is not
# a program; makes the folder $out and its path absolute.
findPrograms() {
  [ -n "$opensees" ] || opensees="$(command -v OpenSees || true)"
  if [ -z "$opensees" ] || [ ! -x "$opensees" ]; then
    echo "OpenSees not found (--opensees PATH or \$OPENSEES): $1 dabs alone"
    opensees=""
  fi
  [ -x "$dabs" ] || { echo "dabs not found at $dabs (--dabs PATH)"; exit 2; }
  mkdir -p "$out"
  out="$(cd "$out" && pwd)"
}
