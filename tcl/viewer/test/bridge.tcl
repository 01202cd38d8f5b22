# SPDX-License-Identifier: MIT
# A small isolated bridge for the viewer's browser test (viewer.test.mjs), run as
#   dabs bridge.tcl outDir
# Units kN, m, t, s. Two piers (elasticBeamColumn, 8 m) carry a 20 m girder (two elasticBeamColumn)
# on two yoshidaBearing elements; the girder end at x = 20 m pounds against a fixed abutment face
# 0.05 m away (nodeToSurface). A 1 Hz sine of 3 m/s^2 along x shakes the bridge for 3 s.
# Writes outDir/bridge.html (recorder Viewer: members with sizes, pads, cap blocks, a joint gap)
# and, to check the page against, outDir/disp.out (Node recorder: time, then x y z of every node),
# and Element recorder files of the contact's gap and force and bearing 21's strain and damage.
set out [lindex $argv 0]
file mkdir $out

model basic -ndm 3 -ndf 6
# piers: bases 1, 11 fixed, tops 2, 12
node 1 0.0 0.0 0.0
node 2 0.0 0.0 8.0
node 11 20.0 0.0 0.0
node 12 20.0 0.0 8.0
fix 1 1 1 1 1 1 1
fix 11 1 1 1 1 1 1
geomTransf Linear 1 0.0 1.0 0.0
geomTransf Linear 2 0.0 0.0 1.0
element elasticBeamColumn 1 1 2 3.0 3.0e7 1.25e7 1.0 0.7 0.7 1
# the second pier: a force-based element with a fiber section (circle D = 1.2 m, E chosen so that EI
# is the first pier's 3.0e7 x 0.7), which the page draws as a solid of its fibers' outline
uniaxialMaterial Elastic 1 [expr {3.0e7 * 0.7 / (acos(-1.0) * pow(0.6, 4) / 4.0)}]
section Fiber 1 -GJ 1.25e7 { patch circ 1 16 4 0.0 0.0 0.0 0.6 0.0 360.0 }
beamIntegration Lobatto 1 1 3
element forceBeamColumn 2 11 12 1 1
# girder nodes 3, 4, 13 with 100 t each
node 3 0.0 0.0 8.0 -mass 100.0 100.0 100.0 0.0 0.0 0.0
node 4 10.0 0.0 8.0 -mass 100.0 100.0 100.0 0.0 0.0 0.0
node 13 20.0 0.0 8.0 -mass 100.0 100.0 100.0 0.0 0.0 0.0
element elasticBeamColumn 31 3 4 2.0 3.0e7 1.25e7 1.0 0.5 2.0 2
element elasticBeamColumn 32 4 13 2.0 3.0e7 1.25e7 1.0 0.5 2.0 2
# bearings: HDR set (a) of verification/bearing/fitted-parameters.md on 0.62 x 0.62 m pads with
# 0.12 m of rubber (the shaking takes them past 300 %, which the strain colour test needs), low
# limits so they fail
set A 0.384
set Tr 0.12
biaxialMaterial Yoshida 1 [expr {0.435794e3 * $A}] [expr {0.0683367 * $Tr}] 0.115167 0.831926 0.698464 0.0393774 0.000947439
element yoshidaBearing 21 2 3 1 -Tr $Tr -Kv 2.0e6 -Kt 500.0 -Kr 8000.0 -limits 0.25 0.5
element yoshidaBearing 22 12 13 1 -Tr $Tr -Kv 2.0e6 -Kt 500.0 -Kr 8000.0 -limits 0.25 0.5
# abutment face at x = 20.05 (corners ordered so that its normal points to -x, towards node 13)
node 41 20.05 -1.0 7.0
node 42 20.05 -1.0 9.0
node 43 20.05 1.0 9.0
node 44 20.05 1.0 7.0
foreach n {41 42 43 44} { fix $n 1 1 1 1 1 1 }
element nodeToSurface 51 13 41 42 43 44 -K 1.0e6

set nodes {1 2 3 4 11 12 13 41 42 43 44}
recorder Node -file [file join $out disp.out] -time -precision 12 -node {*}$nodes -dof 1 2 3 disp
recorder Element -file [file join $out gap.out] -time -precision 12 -ele 51 gap
recorder Element -file [file join $out force.out] -time -precision 12 -ele 51 contactForce
recorder Element -file [file join $out strain.out] -time -precision 12 -ele 21 shearStrain
recorder Element -file [file join $out damage.out] -time -precision 12 -ele 21 damage
recorder Viewer -file [file join $out bridge.html] -title "viewer test bridge" -plots {
  {"girder end x" node 13 1 disp}
  {"contact gap" ele 51 gap 1}
  {"bearing 21 shear strain" ele 21 shearStrain 1}
} -beamSection {{rect 4.0 1.5 31 32} {circle 1.2 1}} -bearingPad {{0.62 0.62 21 22}} \
  -block {{1.5 4.0 1.0 -dz -0.5 2 12}} -gaps {{"Joint" 13 41}}

timeSeries Trig 1 0.0 3.0 1.0 -factor 3.0
pattern UniformExcitation 1 1 -accel 1
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-8 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set ok [analyze 300 0.01]
if {$ok != 0} { error "analysis failed at t = [getTime %.17g]" }
puts "viewer test bridge: 300 steps to t = [getTime %.17g]"
