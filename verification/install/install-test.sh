#!/usr/bin/env bash
# Installs the build into a scratch prefix, then builds and runs a separate project that finds it
# with find_package(dabs), loads the Tcl package from a plain tclsh and imports the Python module.
set -euo pipefail
build=$1
source=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
cmake -S "$source/verification/install/consumer" -B "$scratch/consumer" -DCMAKE_PREFIX_PATH="$scratch/prefix" >/dev/null
cmake --build "$scratch/consumer" >/dev/null
"$scratch/consumer/consumer"
echo 'lappend auto_path [lindex $argv 0]; package require dabs; model basic -ndm 1 -ndf 1; node 1 0.0; puts "package dabs [package present dabs]: nodes [getNodeTags]"' > "$scratch/load.tcl"
tclsh "$scratch/load.tcl" "$scratch/prefix/lib/dabs"
tclsh "$scratch/load.tcl" "$build"
# The Python module, when the build has it: installed in the prefix's site-packages folder.
if compgen -G "$build/python/dabs*.so" >/dev/null; then
  site=$(dirname "$(compgen -G "$scratch/prefix/lib/python3*/site-packages/dabs*.so" | head -n 1)")
  PYTHONPATH="$site" python3 -c 'import dabs; dabs.model("basic", "-ndm", 1, "-ndf", 1); dabs.node(1, 0.0); print("python module dabs from", dabs.__file__.split("/prefix/")[1], ": nodes", dabs.getNodeTags())'
fi
echo "1 passed, 0 failed"
