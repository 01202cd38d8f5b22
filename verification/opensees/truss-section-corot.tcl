# Trusses on a section (`section Uniaxial`, `element truss tag i j secTag`) and the corotational
# truss (`element corotTruss`): a steel bar pulled past yield with A matTag and with a section;
# a shallow two-bar (von Mises) truss pushed through snap-through by displacement control; axial
# periods of a bar with -rho and -cMass. Writes truss-section-corot.csv: case, quantity, value
# (units m, kN, t, s).
# Run: OpenSees truss-section-corot.tcl (or dabs truss-section-corot.tcl)
set out [open truss-section-corot.csv w]
puts $out "case,quantity,value"
proc record {case quantity value} {
  global out
  puts $out [format "%s,%s,%.12e" $case $quantity $value]
}
proc staticAnalysis {node dof step} {
  system BandGeneral; numberer Plain; constraints Plain
  test NormDispIncr 1.0e-12 25; algorithm Newton
  integrator DisplacementControl $node $dof $step; analysis Static
}

# A bar pulled past yield and back: area times steel, and a section carrying A times steel.
foreach {case form} {
  truss-material {element truss 1 1 2 0.01 1}
  truss-section  {element truss 1 1 2 1}
  corot-section  {element corotTruss 1 1 2 1}
} {
  wipe
  model basic -ndm 2 -ndf 2
  node 1 0 0; node 2 2.0 0
  fix 1 1 1; fix 2 0 1
  uniaxialMaterial Steel01 1 3.5e5 2.0e8 0.01
  uniaxialMaterial Elastic 2 [expr {0.01*2.0e8}]
  uniaxialMaterial Steel01 3 [expr {0.01*3.5e5}] [expr {0.01*2.0e8}] 0.01
  section Uniaxial 1 3 P
  eval $form
  timeSeries Linear 1
  pattern Plain 1 1 { load 2 1.0 0 }
  staticAnalysis 2 1 0.002
  for {set k 1} {$k <= 10} {incr k} {
    if {$k == 7} { integrator DisplacementControl 2 1 -0.003 }
    analyze 1
    record $case u$k [nodeDisp 2 1]
    record $case N$k [lindex [eleResponse 1 axialForce] 0]
  }
}

# Von Mises truss: supports at (-a, 0) and (a, 0), apex at (0, h), pushed down through its
# snap-through to 2.5 h.
set a 2.0; set h 0.2
wipe
model basic -ndm 2 -ndf 2
node 1 [expr {-$a}] 0; node 2 $a 0; node 3 0 $h
fix 1 1 1; fix 2 1 1; fix 3 1 0
uniaxialMaterial Elastic 1 2.0e8
element corotTruss 1 1 3 0.001 1
element corotTruss 2 2 3 0.001 1
timeSeries Linear 1
pattern Plain 1 1 { load 3 0 -1.0 }
staticAnalysis 3 2 -0.02
for {set k 1} {$k <= 25} {incr k} {
  analyze 1
  record vonmises w$k [nodeDisp 3 2]
  record vonmises P$k [getLoadFactor 1]
  record vonmises N$k [lindex [eleResponse 1 axialForce] 0]
}

# Axial periods of a bar of one element: lumped and consistent mass (rho per length).
foreach {case form} {
  bar-lumped     {element corotTruss 1 1 2 0.01 1 -rho 7.85}
  bar-consistent {element corotTruss 1 1 2 0.01 1 -rho 7.85 -cMass 1}
  bar-truss-cmass {element truss 1 1 2 1 -rho 7.85 -cMass 1}
} {
  wipe
  model basic -ndm 2 -ndf 2
  node 1 0 0; node 2 2.0 0
  fix 1 1 1; fix 2 0 1
  uniaxialMaterial Elastic 1 2.0e8
  uniaxialMaterial Elastic 2 [expr {0.01*2.0e8}]
  section Uniaxial 1 2 P
  eval $form
  set lambda [eigen -fullGenLapack 1]
  record $case period [expr {2*acos(-1)/sqrt([lindex $lambda 0])}]
}
close $out
