# SPDX-License-Identifier: MIT
# Largest relative error of a viaduct-bench.tcl run against a reference run of the same size, over
# the quantities of the bridge speed study (verification/bridge/tools/speed-study.tcl): peak gaps
# by magnitude, residual gaps relative to the peak of the same gap, peak bearing strains.
#
#   dabs verification/bench/viaduct-compare.tcl run.txt reference.txt
proc load {file} {
  set f [open $file]; set line [gets $f]; set q [gets $f]; close $f
  return [list $line $q]
}
lassign [load [lindex $argv 0]] line q
lassign [load [lindex $argv 1]] refLine ref
set worst 0.0; set which ""
dict for {k v} $q {
  set rv [dict get $ref $k]
  if {[string match residual_* $k]} {
    set scale [expr {abs([dict get $ref peak_[string range $k 9 end]])}]
  } else { set scale [expr {abs($rv)}] }
  set e [expr {abs($v - $rv) / max($scale, 1e-12)}]
  if {$e > $worst} { set worst $e; set which $k }
}
puts [format "%s error %.4f%% on %s" $line [expr {100.0 * $worst}] $which]
