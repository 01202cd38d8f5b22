# SPDX-License-Identifier: MIT
# The error measure of the case study's speed studies (tools/speed-study.tcl and
# verification/bench/bridge-bench.tcl): a run's quantities, and their largest relative difference
# from a reference run's.
#
# Quantities of a three-span run (runCase's result): the peak gaps by magnitude and the residual
# gaps of both inner joints in both directions, and the peak shear strains of the four joint
# bearings. Residuals are compared relative to the peak of the same gap, since they are near zero.
proc quantities {r} {
  set q {}
  foreach k {gap1x gap1y gap2x gap2y} {
    # peaks by magnitude: two peaks of nearly equal size and opposite sign may swap between runs
    dict set q peak_$k [expr {abs([dict get $r peak $k])}]
    dict set q residual_$k [dict get $r last $k]
  }
  foreach bt {2011 2012 3011 3012} { dict set q strain$bt [dict get $r peak strain$bt] }
  return $q
}
proc errorOf {q ref} {
  set worst 0.0; set which ""
  dict for {k v} $q {
    set rv [dict get $ref $k]
    if {[string match residual_* $k]} {
      set scale [expr {abs([dict get $ref peak_[string range $k 9 end]])}]
    } else { set scale [expr {abs($rv)}] }
    set e [expr {abs($v - $rv) / max($scale, 1e-12)}]
    if {$e > $worst} { set worst $e; set which $k }
  }
  return [list $worst $which]
}
