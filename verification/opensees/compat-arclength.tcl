# Compatibility input: `integrator ArcLength arcLength alpha` through the snap-through of a shallow
# arch: two elastic beams with the corotational transformation, pinned at their feet, with a
# downward load at the apex. Load control cannot pass the limit point; arc length follows the load
# factor down and up again. Blocks: three (arcLength, alpha) pairs; each row: load factor, apex
# vertical displacement and rotation of a foot. hsconstraint-as-arclength.tcl checks
# `integrator HSConstraint s 1 0 1`, the same constraint, against the first block.
proc arch {tol} {
  wipe
  model basic -ndm 2 -ndf 3
  node 1 0.0 0.0; node 2 5.0 0.25; node 3 10.0 0.0
  fix 1 1 1 0; fix 3 1 1 0
  geomTransf Corotational 1
  element elasticBeamColumn 1 1 2 0.01 200000.0 0.00001 1
  element elasticBeamColumn 2 2 3 0.01 200000.0 0.00001 1
  timeSeries Linear 1
  pattern Plain 1 1 { load 2 0.0 -1.0 0.0 }
  system BandGeneral; numberer Plain; constraints Plain; test NormDispIncr $tol 50
  algorithm Newton
}
if {![info exists arcLengthCases]} {
  # each case: test tolerance, then the integrator command's arguments
  set arcLengthCases {{1e-10 ArcLength 0.02 0.0} {1e-9 ArcLength 0.05 0.1} {1e-9 ArcLength 0.02 1.0}}
}
set out [open compat-arclength.out w]
foreach case $arcLengthCases {
  puts $out "[lrange $case 1 end]: lambda uy2 rz1"
  arch [lindex $case 0]
  integrator {*}[lrange $case 1 end]
  analysis Static
  for {set i 1} {$i <= 40} {incr i} {
    if {[analyze 1] != 0} break
    puts $out [format "%.10g %.10g %.10g" [getLoadFactor 1] [nodeDisp 2 2] [nodeDisp 1 3]]
  }
}
close $out
