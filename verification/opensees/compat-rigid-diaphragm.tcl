# Compatibility input: `rigidDiaphragm perpDirn rNode cNode..` on a one-storey 3D frame: four
# elastic columns of different stiffness carry a floor modelled as a rigid diaphragm whose retained
# node sits at the centre of mass, off the column centroid (the retained node's out-of-plane dofs
# fixed, as OpenSees' 3D frame examples do). A lateral load with an eccentricity twists the floor.
# A second diaphragm in the xz plane (perpDirn 2) ties a wall-like pair of nodes. Each row: one
# node's six displacements under the load. A second block: a 2D two-bay portal whose floor nodes
# share the horizontal displacement (`rigidDiaphragm 1`), and a node tied in-plane to the retained
# node (`rigidDiaphragm 3`). (OpenSees 3.8 mishandles a retained node that is itself constrained,
# so the input avoids such chains.)
wipe
model basic -ndm 3 -ndf 6
set h 3.0
node 1 0.0 0.0 0.0; node 2 6.0 0.0 0.0; node 3 6.0 4.0 0.0; node 4 0.0 4.0 0.0
node 5 0.0 0.0 $h;  node 6 6.0 0.0 $h;  node 7 6.0 4.0 $h;  node 8 0.0 4.0 $h
node 9 2.5 2.2 $h
foreach n {1 2 3 4} { fix $n 1 1 1 1 1 1 }
fix 9 0 0 1 1 1 0
rigidDiaphragm 3 9 5 6 7 8
geomTransf Linear 1 1.0 0.0 0.0
set E 30000.0; set G 12500.0
element elasticBeamColumn 1 1 5 0.16 $E $G 0.0036 0.00213 0.00213 1
element elasticBeamColumn 2 2 6 0.25 $E $G 0.0088 0.0052 0.0052 1
element elasticBeamColumn 3 3 7 0.16 $E $G 0.0036 0.00213 0.00213 1
element elasticBeamColumn 4 4 8 0.36 $E $G 0.018 0.0108 0.0108 1
# a short cantilever wall in the xz plane at x = 8, its top pair tied by a diaphragm normal to y
node 10 8.0 0.0 0.0; node 11 8.0 0.0 $h; node 12 9.0 0.0 $h
fix 10 1 1 1 1 1 1
fix 12 0 1 0 1 0 1
rigidDiaphragm 2 11 12
element elasticBeamColumn 5 10 11 0.2 $E $G 0.004 0.002 0.002 1
geomTransf Linear 2 0.0 1.0 0.0
element elasticBeamColumn 6 12 10 0.2 $E $G 0.004 0.002 0.002 2
timeSeries Linear 1
pattern Plain 1 1 {
  load 9 100.0 40.0 0.0 0.0 0.0 25.0
  load 11 30.0 0.0 -10.0 0.0 0.0 0.0
}
system BandGeneral; numberer Plain; constraints Transformation; test NormDispIncr 1e-12 10
algorithm Newton; integrator LoadControl 1.0; analysis Static
analyze 1
set out [open compat-rigid-diaphragm.out w]
puts $out "node ux uy uz rx ry rz"
foreach n {5 6 7 8 9 11 12} {
  set row $n
  foreach v [nodeDisp $n] { lappend row [format %.10g $v] }
  puts $out [join $row " "]
}
puts $out "2D: node ux uy rz"
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0; node 2 5.0 0.0; node 3 11.0 0.0
node 4 0.0 3.5; node 5 5.0 3.5; node 6 11.0 3.5; node 7 7.0 5.0
fix 1 1 1 1; fix 2 1 1 1; fix 3 1 1 0
rigidDiaphragm 1 5 4 6
rigidDiaphragm 3 5 7
geomTransf Linear 1
element elasticBeamColumn 1 1 4 0.09 25000.0 0.000675 1
element elasticBeamColumn 2 2 5 0.16 25000.0 0.00213 1
element elasticBeamColumn 3 3 6 0.09 25000.0 0.000675 1
element elasticBeamColumn 4 4 5 0.12 25000.0 0.0016 1
element elasticBeamColumn 5 5 6 0.12 25000.0 0.0016 1
timeSeries Linear 1
pattern Plain 1 1 {
  load 4 20.0 -30.0 0.0
  load 6 0.0 -30.0 5.0
  load 7 0.0 -10.0 0.0
}
system BandGeneral; numberer Plain; constraints Transformation; test NormDispIncr 1e-12 10
algorithm Newton; integrator LoadControl 1.0; analysis Static
analyze 1
foreach n {4 5 6 7} {
  set row $n
  foreach v [nodeDisp $n] { lappend row [format %.10g $v] }
  puts $out [join $row " "]
}
close $out
