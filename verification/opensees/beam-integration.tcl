# Integration rules of force- and displacement-based beam-columns as the element command gives
# them: the older form "nIP secTag transfTag" (forceBeamColumn and nonlinearBeamColumn integrate
# with Gauss-Lobatto, dispBeamColumn with Gauss-Legendre), the rule written after the
# transformation tag (as one list or as separate words), and -lMass / -cMass with -mass.
# A 2D steel cantilever (fiber section, Steel01) is pushed at its tip; the periods of a
# three-element cantilever with distributed mass follow. Writes beam-integration.csv: case,
# quantity, value (units m, kN, s).
# Run: OpenSees beam-integration.tcl (or dabs beam-integration.tcl)
set out [open beam-integration.csv w]
puts $out "case,quantity,value"
proc record {case quantity value} {
  global out
  puts $out [format "%s,%s,%.12e" $case $quantity $value]
}

set L 3.0
proc cantilever {} {
  global L
  wipe
  model basic -ndm 2 -ndf 3
  node 1 0 0; node 2 0 $L
  fix 1 1 1 1
  geomTransf Linear 1
  uniaxialMaterial Steel01 1 4.0e5 2.0e8 0.02
  section Fiber 1 {
    patch rect 1 16 1 -0.2 -0.1 0.2 0.1
  }
  section Elastic 2 2.0e8 0.08 1.0e-3
}
proc push {case} {
  timeSeries Linear 1
  pattern Plain 1 1 { load 2 1.0 0 0 }
  system BandGeneral; numberer Plain; constraints Plain
  test NormDispIncr 1.0e-10 50; algorithm Newton
  integrator DisplacementControl 2 1 0.01; analysis Static
  for {set k 1} {$k <= 6} {incr k} {
    analyze 1
    set f [eleResponse 1 localForce]
    record $case shear$k [lindex $f 1]
    record $case moment$k [lindex $f 2]
  }
}

set forms {
  disp-old           {element dispBeamColumn 1 1 2 3 1 1}
  disp-old-lobatto   {element dispBeamColumn 1 1 2 3 1 1 -integration Lobatto}
  disp-inline-list   {element dispBeamColumn 1 1 2 1 "Lobatto 1 3"}
  force-old          {element forceBeamColumn 1 1 2 4 1 1}
  nonlinear-old      {element nonlinearBeamColumn 1 1 2 4 1 1}
  force-old-legendre {element forceBeamColumn 1 1 2 4 1 1 -integration Legendre}
  force-inline-list  {element forceBeamColumn 1 1 2 1 {Legendre 1 3}}
  force-inline-words {element forceBeamColumn 1 1 2 1 Lobatto 1 4}
  force-inline-hinge {element forceBeamColumn 1 1 2 1 HingeRadau 1 0.3 1 0.3 2}
}
foreach {case command} $forms {
  cantilever
  eval $command
  push $case
}

# Distributed mass: lumped by default and with -lMass, consistent with -cMass (OpenSees 3.8 passes
# -cMass to displacement-based elements only).
set massForms {
  disp-lumped   {dispBeamColumn $e $i $j 1 "Legendre 2 3" -mass 2.0 -lMass}
  disp-cmass    {dispBeamColumn $e $i $j 1 "Legendre 2 3" -mass 2.0 -cMass}
  force-lumped  {forceBeamColumn $e $i $j 1 "Lobatto 2 4" -mass 2.0 -lMass}
  force-default {forceBeamColumn $e $i $j 3 2 1 -mass 2.0}
}
foreach {case command} $massForms {
  cantilever
  node 3 0 [expr {2*$L}]; node 4 0 [expr {3*$L}]
  foreach e {1 2 3} i {1 2 3} j {2 3 4} { eval element [subst $command] }
  set lambda [eigen -fullGenLapack 2]
  foreach mode {1 2} value $lambda { record mass-$case period$mode [expr {2*acos(-1)/sqrt($value)}] }
}
close $out
