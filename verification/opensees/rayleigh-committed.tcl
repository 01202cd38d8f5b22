# Rayleigh damping proportional to the committed tangent (rayleigh 0 0 0 betaKcomm) and to the
# current tangent (rayleigh 0 betaK 0 0) on yielding beam-columns: a 2D steel cantilever (fiber
# section, Steel01) with a tip mass under a sine ground acceleration, force- and
# displacement-based. Writes rayleigh-committed.csv: case, quantity, value (units m, kN, t, s).
# Run: OpenSees rayleigh-committed.tcl (or dabs rayleigh-committed.tcl)
set out [open rayleigh-committed.csv w]
puts $out "case,quantity,value"
proc record {case quantity value} {
  global out
  puts $out [format "%s,%s,%.12e" $case $quantity $value]
}

foreach {case type factors} {
  force-committed forceBeamColumn {0.0 0.0 0.0 0.004}
  disp-committed  dispBeamColumn  {0.0 0.0 0.0 0.004}
  force-current   forceBeamColumn {0.0 0.004 0.0 0.0}
  force-mixed     forceBeamColumn {0.3 0.0 0.002 0.002}
} {
  wipe
  model basic -ndm 2 -ndf 3
  node 1 0 0; node 2 0 3.0
  fix 1 1 1 1
  mass 2 40.0 40.0 0.0
  geomTransf PDelta 1
  uniaxialMaterial Steel01 1 3.0e5 2.0e8 0.01
  section Fiber 1 {
    patch rect 1 12 1 -0.15 -0.1 0.15 0.1
  }
  if {$type eq "forceBeamColumn"} {
    element forceBeamColumn 1 1 2 1 Lobatto 1 5
  } else {
    element dispBeamColumn 1 1 2 1 Legendre 1 3
  }
  timeSeries Trig 1 0.0 2.0 0.4 -factor 6.0
  pattern UniformExcitation 1 1 -accel 1
  rayleigh {*}$factors
  constraints Plain; system BandGeneral; numberer Plain
  test NormDispIncr 1.0e-12 25; algorithm Newton
  integrator Newmark 0.5 0.25; analysis Transient
  for {set k 1} {$k <= 150} {incr k} {
    analyze 1 0.01
    if {$k % 10 == 0} {
      record $case ux$k [nodeDisp 2 1]
      record $case shear$k [lindex [eleResponse 1 localForce] 1]
    }
  }
}
close $out
