# Compatibility input: fiber sections whose fibers are not symmetric about the coordinates they
# are given in. OpenSees takes a fiber section's strains about the fibers' area centroid (unless
# `section Fiber tag -noCentroid`), so the reference axis of an unsymmetric section is its
# centroid, not y = 0. Three blocks:
# - a 2D portal frame (two force-based columns of a concrete rectangle 0.4 x 0.6 m with the
#   bars on one face only, an elastic beam) under gravity, then a lateral load: the column-top
#   displacements and rotations at both stages;
# - the same frame with -noCentroid;
# - a 3D cantilever (displacement-based, bars at one corner of a 0.5 x 0.5 m square) under axial
#   load and biaxial tip loads: the tip's six displacements.
proc columnSection {tag noCentroid} {
  set opts [expr {$noCentroid ? "-noCentroid" : ""}]
  section Fiber $tag {*}$opts {
    patch rect 1 10 2 -0.3 -0.2 0.3 0.2
    layer straight 2 4 0.0008 0.25 -0.15 0.25 0.15
  }
}

proc portal {noCentroid out} {
  wipe
  model basic -ndm 2 -ndf 3
  node 1 0.0 0.0; node 2 6.0 0.0; node 3 0.0 4.0; node 4 6.0 4.0
  fix 1 1 1 1; fix 2 1 1 1
  uniaxialMaterial Concrete01 1 -30000.0 -0.002 -6000.0 -0.006
  uniaxialMaterial Steel01 2 420000.0 2.0e8 0.01
  columnSection 1 $noCentroid
  geomTransf Linear 1
  geomTransf PDelta 2
  element forceBeamColumn 1 1 3 2 Lobatto 1 5
  element forceBeamColumn 2 2 4 2 Lobatto 1 5
  element elasticBeamColumn 3 3 4 0.24 3.0e7 0.0072 1
  timeSeries Linear 1
  pattern Plain 1 1 { load 3 0.0 -600.0 0.0; load 4 0.0 -600.0 0.0 }
  constraints Plain; numberer Plain; system BandGeneral
  test NormDispIncr 1e-12 20; algorithm Newton
  integrator LoadControl 0.1; analysis Static
  analyze 10
  puts $out "stage node ux uy rz"
  foreach n {3 4} {
    set row "1 $n"
    foreach d {1 2 3} { lappend row [format %.12g [nodeDisp $n $d]] }
    puts $out $row
  }
  loadConst -time 0.0
  pattern Plain 2 1 { load 3 120.0 0.0 0.0 }
  integrator LoadControl 0.1
  analyze 10
  foreach n {3 4} {
    set row "2 $n"
    foreach d {1 2 3} { lappend row [format %.12g [nodeDisp $n $d]] }
    puts $out $row
  }
}

set out [open compat-unsymmetric-section.out w]
portal 0 $out
puts $out "noCentroid"
portal 1 $out

wipe
model basic -ndm 3 -ndf 6
node 1 0.0 0.0 0.0; node 2 0.0 0.0 3.0
fix 1 1 1 1 1 1 1
uniaxialMaterial Concrete01 1 -30000.0 -0.002 -6000.0 -0.006
uniaxialMaterial Steel01 2 420000.0 2.0e8 0.01
section Fiber 1 -GJ 1.0e5 {
  patch rect 1 8 8 -0.25 -0.25 0.25 0.25
  fiber 0.2 0.2 0.002 2
  fiber 0.2 0.1 0.002 2
  fiber 0.1 0.2 0.002 2
}
geomTransf Linear 1 1.0 0.0 0.0
element dispBeamColumn 1 1 2 1 Legendre 1 4
timeSeries Linear 1
pattern Plain 1 1 { load 2 20.0 -15.0 -800.0 0.0 0.0 0.0 }
constraints Plain; numberer Plain; system BandGeneral
test NormDispIncr 1e-12 20; algorithm Newton
integrator LoadControl 0.1; analysis Static
analyze 10
puts $out "3D: ux uy uz rx ry rz"
set row {}
foreach d {1 2 3 4 5 6} { lappend row [format %.12g [nodeDisp 2 $d]] }
puts $out [join $row " "]
close $out
