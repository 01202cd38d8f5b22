# SPDX-License-Identifier: MIT
# Two isolated girder spans pounding across one expansion joint under the Takatori record (units kN,
# m, s, t): spans of 30 m and 50 m on rubber bearings over three 10 m piers, a 50 mm joint over the
# middle pier. Prints the peak closing and opening, the residual joint gap and the number of impacts.
set gap 0.05; set scale 1.0; set tRecord 10.0; set tRest 5.0  ;# joint gap (m), record's scale, record and rest (s)
set record [file join [file dirname [info script]] .. verification data RSN1120_KOBE_TAK090.AT2]
model basic -ndm 3 -ndf 6                                 ;# 3D, 6 dofs a node
geomTransf Linear 1 1 0 0                                 ;# piers: local x-z plane contains X
geomTransf Linear 2 0 0 1                                 ;# girders
# Piers (circular RC, D = 2 m, elastic, cracked EI) at x = 0, 30, 80: base nodes 1-3, tops 11-13
foreach p {1 2 3} x {0 30 80} {
  node $p $x 0 0; fix $p 1 1 1 1 1 1
  node 1$p $x 0 10 -mass 150 150 150 0 0 0               ;# 150 t pier cap
  element elasticBeamColumn $p $p 1$p 3.14 2.5e7 1.04e7 1.57 0.55 0.55 1
}
# Bearing seats on pier 2, one each side of the joint, rigidly tied to the pier top
foreach n {21 22} x [list [expr {30 - $gap/2}] [expr {30 + $gap/2}]] { node $n $x 0 10; rigidLink beam 12 $n }
set m 15.0   ;# Girders (steel box with deck, 15 t/m), 2 elements each; nodes on bearing tops and mid-span
foreach {a mid b x0 x1} [list 31 32 33 0 [expr {30 - $gap/2}] 41 42 43 [expr {30 + $gap/2}] 80] {
  set L [expr {$x1 - $x0}]
  node $a $x0 0 10 -mass [expr {$m*$L/4}] [expr {$m*$L/4}] [expr {$m*$L/4}] 0 0 0
  node $mid [expr {($x0 + $x1)/2}] 0 10 -mass [expr {$m*$L/2}] [expr {$m*$L/2}] [expr {$m*$L/2}] 0 0 0
  node $b $x1 0 10 -mass [expr {$m*$L/4}] [expr {$m*$L/4}] [expr {$m*$L/4}] 0 0 0
  element elasticBeamColumn $a $a $mid 0.6 2.0e8 7.7e7 0.5 12.0 0.8 2
  element elasticBeamColumn $mid $mid $b 0.6 2.0e8 7.7e7 0.5 12.0 0.8 2
}
# Motion only in the bridge's plane: no transverse sway, roll or twist of piers and girders
foreach n {11 12 13 31 32 33 41 42 43} { fix $n 0 1 0 1 0 1 }
# HDR bearings, set (a) of verification/bearing/fitted-parameters.md for 1.6 m^2 of rubber, Tr 0.2 m;
# vertical stiffness Kv = Ec A / Tr (shape factor 10); bearing i (cap or seat) j (girder)
biaxialMaterial Yoshida 1 [expr {0.435794*1600}] [expr {0.0683367*0.2}] 0.115167 0.831926 0.698464 0.0393774 0.000947439
foreach {tag i j} {1 11 31  2 21 33  3 22 41  4 13 43} { element yoshidaBearing 10$tag $i $j 1 -Tr 0.2 -Kv 3.9e6 }
# The joint: girder 1's end face (4 nodes tied to its end node, normal +X) against girder 2's end node
foreach {n y z} {51 -5 -1.25  52 -5 1.25  53 5 1.25  54 5 -1.25} { node $n [expr {30 - $gap/2}] $y [expr {10 + $z}]; rigidLink beam 33 $n }
element nodeToSurface 200 41 51 54 53 52 -K 3.0e6 -e 0.65 -masses 450 750   ;# K = EA/L of a girder, span masses
# Damping: the bearings' hysteresis; stiffness-proportional on piers and girders (1.7 % at the piers' 0.38 s)
region 1 -ele 1 2 3 31 32 41 42 -rayleigh 0 0 0 0.002
# The record along X: the file is in g (PEER header NPTS, DT read from it), times 9.81 m/s^2 and scale
timeSeries Path 1 -filePath $record -factor [expr {9.81*$scale}]
pattern UniformExcitation 1 1 -accel 1
constraints Transformation; numberer RCM; system BandGeneral
test NormDispIncr 1e-6 30; algorithm Newton; integrator Newmark 0.5 0.25; analysis Transient
# Short steps around impacts; after every step follow the joint gap and count closings
set minGap $gap; set maxGap $gap; set impacts 0; set wasClosed 0
contactStepping -maxStep 0.001 -eachStep {
  set jointGap [expr {$gap + [nodeDisp 41 1] - [nodeDisp 33 1]}]
  set minGap [expr {min($minGap, $jointGap)}]; set maxGap [expr {max($maxGap, $jointGap)}]
  set closed [expr {[eleResponse 200 status] != 0}]
  if {$closed && !$wasClosed} { incr impacts }; set wasClosed $closed
}
if {[analyze [expr {int($tRecord/0.01)}] 0.01] != 0} { puts "FAILED: analysis stopped at [getTime] s"; exit 1 }
remove loadPattern 1                                      ;# ground at rest: the bridge settles
if {[analyze [expr {int($tRest/0.01)}] 0.01] != 0} { puts "FAILED: analysis stopped at [getTime] s"; exit 1 }
puts [format "Takatori EW x %.2f, first %.0f s, then %.0f s at rest; joint gap %.0f mm" $scale $tRecord $tRest [expr {$gap*1000}]]
puts [format "peak closing: gap %.1f mm (negative: contact penetration)" [expr {$minGap*1000}]]
puts [format "peak opening: gap %.1f mm" [expr {$maxGap*1000}]]
puts [format "residual gap: %.1f mm" [expr {$jointGap*1000}]]
puts "impacts: $impacts"
if {$impacts < 1 || $minGap < -0.01} { puts "FAILED: no pounding, or the contact let the girders pass"; exit 1 }
