#!/bin/sh
# The main job of DABS: the three-span isolated bridge, three cases (no pounding,
# pounding, pounding with restrainers and bumpers), report in ./bridge-out/report.md.
#   verification/bridge/run-main.sh ?build dir? ?args of bridge.tcl?
here=$(dirname "$0")
build=${1:-build}
[ $# -gt 0 ] && shift
exec "$build/dabs" "$here/bridge.tcl" "$@"
