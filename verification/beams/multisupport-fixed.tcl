# SPDX-License-Identifier: MIT
# Imposed support motions on fixed dofs (`pattern MultiSupport`, `imposedSupportMotion`): runs the
# input verification/opensees/multisupport-fixed.tcl, compares every displacement with OpenSees
# 3.8.0's CSV for it (Transformation handler), and checks that the support given a displacement
# history follows it exactly (linear interpolation of the 0.1 s samples).
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] .. lib opensees-csv.tcl]

source [openseesReference multisupport-fixed.tcl]
set r [compareOpenSeesCsv multisupport-fixed.csv [openseesReference multisupport-fixed.csv] 1e-7 1e-12]

set samples {0.0 0.002 0.006 0.004 -0.002 -0.005 -0.003 0.0 0.001 0.0 0.0}
foreach k {20 40 60 80} {
  set t [expr {0.01*$k}]
  set i [expr {int(floor($t/0.1 + 1e-9))}]
  set frac [expr {$t/0.1 - $i}]
  set expected [expr {[lindex $samples $i] + $frac*([lindex $samples [expr {$i+1}]] - [lindex $samples $i])}]
  checkAbs "fixed support 4 follows its displacement history at t = $t" [dict get $r step$k,u4] $expected 1e-12
}
finish
