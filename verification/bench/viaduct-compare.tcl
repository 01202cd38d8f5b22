# SPDX-License-Identifier: MIT
# Largest relative error of a viaduct-bench.tcl run against a reference run of the same size, over
# the quantities of the bridge speed study: peak gaps by magnitude, residual gaps relative to the
# peak of the same gap, peak bearing strains (the measure of verification/bridge/tools/
# speed-error.tcl, on every joint and bearing of the viaduct).
#
#   dabs verification/bench/viaduct-compare.tcl run.txt reference.txt
source [file join [file dirname [info script]] .. bridge tools speed-error.tcl]
proc load {file} {
  set f [open $file]; set line [gets $f]; set q [gets $f]; close $f
  return [list $line $q]
}
lassign [load [lindex $argv 0]] line q
lassign [load [lindex $argv 1]] refLine ref
lassign [errorOf $q $ref] worst which
puts [format "%s error %.4f%% on %s" $line [expr {100.0 * $worst}] $which]
