# Member loads (eleLoad -beamUniform, -beamPoint) on elastic, force- and displacement-based
# beam-columns in 2D and 3D, static, in a Plain pattern with a Linear series; Linear, PDelta and
# Corotational transformations. Writes
# eleload-beam.csv: case, quantity, value (SI units: m, kN).
# Run: OpenSees eleload-beam.tcl (or dabs eleload-beam.tcl)
set out [open eleload-beam.csv w]
puts $out "case,quantity,value"
proc record {case quantity value} {
  global out
  puts $out [format "%s,%s,%.12e" $case $quantity $value]
}

set L 6.0; set E 200.0e6; set A 0.01; set Iz 1.0e-4; set Iy 2.0e-4; set G 80.0e6; set J 3.0e-4

proc solve {} {
  system BandGeneral; numberer Plain; constraints Plain
  test NormDispIncr 1.0e-12 20; algorithm Newton
  integrator LoadControl 0.5; analysis Static
  analyze 2
}

# 2D element of a type between nodes i and j with transformation 1.
proc element2d {type tag i j} {
  global E A Iz
  if {$type eq "elastic"} {
    element elasticBeamColumn $tag $i $j $A $E $Iz 1
  } elseif {$type eq "force"} {
    element forceBeamColumn $tag $i $j 1 1
  } else {
    element dispBeamColumn $tag $i $j 1 2
  }
}
proc model2d {type} {
  global E A Iz
  wipe
  model basic -ndm 2 -ndf 3
  geomTransf Linear 1
  section Elastic 1 $E $A $Iz
  beamIntegration Lobatto 1 1 5
  beamIntegration Legendre 2 1 3
}

# Simply supported beam of two elements, full-length uniform load with an axial part.
foreach type {elastic force disp} {
  model2d $type
  node 1 0 0; node 2 [expr {$L/2}] 0; node 3 $L 0
  fix 1 1 1 0; fix 3 0 1 0
  element2d $type 1 1 2; element2d $type 2 2 3
  timeSeries Linear 1
  pattern Plain 1 1 { eleLoad -ele 1 2 -type -beamUniform -10.0 2.0 }
  solve
  record ss-uniform-$type uy-mid [nodeDisp 2 2]
  record ss-uniform-$type rz-end [nodeDisp 1 3]
  record ss-uniform-$type ux-end [nodeDisp 3 1]
  set f [eleResponse 1 localForce]
  for {set k 0} {$k < 6} {incr k} { record ss-uniform-$type localForce$k [lindex $f $k] }
}

# Cantilever of one element, point load at 0.3 L with an axial part, then a partial uniform load.
foreach type {elastic force disp} {
  model2d $type
  node 1 0 0; node 2 $L 0
  fix 1 1 1 1
  element2d $type 1 1 2
  timeSeries Linear 1
  pattern Plain 1 1 { eleLoad -ele 1 -type -beamPoint -20.0 0.3 5.0 }
  solve
  record cant-point-$type uy-tip [nodeDisp 2 2]
  record cant-point-$type rz-tip [nodeDisp 2 3]
  record cant-point-$type ux-tip [nodeDisp 2 1]
  set f [eleResponse 1 localForce]
  for {set k 0} {$k < 6} {incr k} { record cant-point-$type localForce$k [lindex $f $k] }
}
foreach type {elastic force} {
  model2d $type
  node 1 0 0; node 2 $L 0
  fix 1 1 1 1
  element2d $type 1 1 2
  timeSeries Linear 1
  pattern Plain 1 1 { eleLoad -range 1 1 -type -beamUniform -8.0 0.0 0.25 0.75 }
  solve
  record cant-partial-$type uy-tip [nodeDisp 2 2]
  record cant-partial-$type rz-tip [nodeDisp 2 3]
}

# Cantilever with a load varying linearly over [0.2 L, 0.9 L] (intensities at bOverL given).
foreach type {elastic force} {
  model2d $type
  node 1 0 0; node 2 $L 0
  fix 1 1 1 1
  element2d $type 1 1 2
  timeSeries Linear 1
  pattern Plain 1 1 { eleLoad -ele 1 -type -beamUniform -4.0 1.0 0.2 0.9 -10.0 3.0 }
  solve
  record cant-trapezoid-$type uy-tip [nodeDisp 2 2]
  record cant-trapezoid-$type rz-tip [nodeDisp 2 3]
  record cant-trapezoid-$type ux-tip [nodeDisp 2 1]
}

# The loads scale with the series and leave with their pattern: load at factor 1, hold it
# (loadConst), remove the pattern and analyse again.
model2d elastic
node 1 0 0; node 2 $L 0
fix 1 1 1 1
element2d elastic 1 1 2
timeSeries Linear 1
pattern Plain 1 1 { eleLoad -ele 1 -type -beamUniform -10.0 }
system BandGeneral; numberer Plain; constraints Plain
test NormDispIncr 1.0e-12 20; algorithm Newton
integrator LoadControl 0.5; analysis Static
analyze 1
record series-elastic uy-tip-half [nodeDisp 2 2]
analyze 1
record series-elastic uy-tip-full [nodeDisp 2 2]
loadConst -time 0.0
remove loadPattern 1
analyze 1
record series-elastic uy-tip-removed [nodeDisp 2 2]

# 3D cantilever along x with vecxz = global z (local y = global y, local z = global z).
foreach type {elastic force disp} {
  wipe
  model basic -ndm 3 -ndf 6
  geomTransf Linear 1 0 0 1
  section Elastic 1 $E $A $Iz $Iy $G $J
  beamIntegration Lobatto 1 1 5
  beamIntegration Legendre 2 1 3
  node 1 0 0 0; node 2 $L 0 0
  fix 1 1 1 1 1 1 1
  if {$type eq "elastic"} {
    element elasticBeamColumn 1 1 2 $A $E $G $J $Iy $Iz 1
  } elseif {$type eq "force"} {
    element forceBeamColumn 1 1 2 1 1
  } else {
    element dispBeamColumn 1 1 2 1 2
  }
  timeSeries Linear 1
  pattern Plain 1 1 {
    eleLoad -ele 1 -type -beamUniform -4.0 3.0 1.5
    eleLoad -ele 1 -type -beamPoint 6.0 -7.0 0.6 -2.0
  }
  solve
  foreach dof {1 2 3 4 5 6} { record cant3d-$type u$dof [nodeDisp 2 $dof] }
  set f [eleResponse 1 localForce]
  for {set k 0} {$k < 12} {incr k} { record cant3d-$type localForce$k [lindex $f $k] }
}
# 3D cantilever with a load varying linearly over [0.1 L, 0.8 L] in all three directions.
foreach type {elastic force} {
  wipe
  model basic -ndm 3 -ndf 6
  geomTransf Linear 1 0 0 1
  section Elastic 1 $E $A $Iz $Iy $G $J
  beamIntegration Lobatto 1 1 5
  node 1 0 0 0; node 2 $L 0 0
  fix 1 1 1 1 1 1 1
  if {$type eq "elastic"} {
    element elasticBeamColumn 1 1 2 $A $E $G $J $Iy $Iz 1
  } else {
    element forceBeamColumn 1 1 2 1 1
  }
  timeSeries Linear 1
  pattern Plain 1 1 { eleLoad -ele 1 -type -beamUniform -2.0 1.0 0.5 0.1 0.8 -6.0 4.0 1.5 }
  solve
  foreach dof {1 2 3 5 6} { record cant3d-trapezoid-$type u$dof [nodeDisp 2 $dof] }
}
# Geometrically nonlinear transformations: a column of two elements under a lateral member load
# and a compressive tip load (below its buckling load), loaded in ten steps.
foreach transf {PDelta Corotational} {
  foreach type {elastic force} {
    model2d $type
    geomTransf $transf 2
    node 1 0 0; node 2 0 3.0; node 3 0 6.0
    fix 1 1 1 1
    if {$type eq "elastic"} {
      element elasticBeamColumn 1 1 2 $A $E $Iz 2
      element elasticBeamColumn 2 2 3 $A $E $Iz 2
    } else {
      element forceBeamColumn 1 1 2 2 1
      element forceBeamColumn 2 2 3 2 1
    }
    timeSeries Linear 1
    pattern Plain 1 1 {
      eleLoad -ele 1 2 -type -beamUniform -3.0
      load 3 0 -60.0 0
    }
    system BandGeneral; numberer Plain; constraints Plain
    test NormDispIncr 1.0e-12 30; algorithm Newton
    integrator LoadControl 0.1; analysis Static
    analyze 10
    record column-$transf-$type ux-top [nodeDisp 3 1]
    record column-$transf-$type uy-top [nodeDisp 3 2]
    set f [eleResponse 1 localForce]
    for {set k 0} {$k < 6} {incr k} { record column-$transf-$type localForce$k [lindex $f $k] }
  }
}
close $out
