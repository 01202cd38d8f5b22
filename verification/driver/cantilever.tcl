# SPDX-License-Identifier: MIT
# Elastic cantilevers (elasticBeamColumn, Linear transformation, static analysis).
#
# Source: elementary beam theory (e.g. Gere & Timoshenko, Mechanics of Materials, Appendix G,
# cantilever cases 1 and 4; torsion of a circular/prismatic bar): tip load P: deflection
# P L^3 / (3 E I), rotation P L^2 / (2 E I); tip moment M: deflection M L^2 / (2 E I), rotation
# M L / (E I); axial force N: N L / (E A); torque T: twist T L / (G J). The cubic Hermitian
# element reproduces these exactly at the nodes, so the tolerance is round-off.
source [file join [file dirname [info script]] .. lib check.tcl]

set TOL 1e-9
set nEle 5

# ---------------------------------------------------------------- 2D, along global X
set L 120.0; set E 29000.0; set A 20.0; set I 800.0
set P 3.0; set M 150.0; set N 40.0
model basic -ndm 2 -ndf 3
for {set i 0} {$i <= $nEle} {incr i} { node [expr {$i + 1}] [expr {$L * $i / $nEle}] 0.0 }
fix 1 1 1 1
geomTransf Linear 1
for {set i 1} {$i <= $nEle} {incr i} { element elasticBeamColumn $i $i [expr {$i + 1}] $A $E $I 1 }
set tip [expr {$nEle + 1}]
timeSeries Linear 1
# case 1: tip shear P and axial N
pattern Plain 1 1 { load $tip $N $P 0.0 }
constraints Plain; numberer RCM; system BandGeneral
test NormDispIncr 1e-12 5; algorithm Linear
integrator LoadControl 1.0
analysis Static
checkTrue "2D cantilever: analyze returns 0" [expr {[analyze 1] == 0}]
check "2D cantilever tip deflection PL^3/3EI" [nodeDisp $tip 2] [expr {$P * $L ** 3 / (3.0 * $E * $I)}] $TOL
check "2D cantilever tip rotation PL^2/2EI" [nodeDisp $tip 3] [expr {$P * $L ** 2 / (2.0 * $E * $I)}] $TOL
check "2D cantilever axial PL/EA" [nodeDisp $tip 1] [expr {$N * $L / ($E * $A)}] $TOL
reactions
check "2D cantilever base moment reaction -P L" [nodeReaction 1 3] [expr {-$P * $L}] $TOL
# case 2: tip moment only (remove the first pattern, restart from zero)
remove loadPattern 1
reset
pattern Plain 2 1 { load $tip 0.0 0.0 $M }
setTime 0.0
analyze 1
check "2D cantilever tip moment: deflection ML^2/2EI" [nodeDisp $tip 2] [expr {$M * $L ** 2 / (2.0 * $E * $I)}] $TOL
check "2D cantilever tip moment: rotation ML/EI" [nodeDisp $tip 3] [expr {$M * $L / ($E * $I)}] $TOL
# case 3: loadConst keeps the moment; then an imposed tip deflection (sp) in a new pattern:
# the tip force is 3 E I d / L^3 minus the moment's share (superposition of cases 1 and 2)
loadConst -time 0.0
set d 0.5
pattern Plain 3 1 { sp $tip 2 $d }
analyze 1
check "2D cantilever loadConst + sp: tip deflection imposed" [nodeDisp $tip 2] $d $TOL
reactions
# u = F L^3/3EI + M L^2/2EI = d  =>  F = (d - M L^2/2EI) 3EI/L^3 (reaction at the tip = F)
check "2D cantilever loadConst + sp: tip reaction (d - ML^2/2EI) 3EI/L^3" [nodeReaction $tip 2] \
  [expr {($d - $M * $L ** 2 / (2.0 * $E * $I)) * 3.0 * $E * $I / $L ** 3}] $TOL
check "2D cantilever loadConst + sp: tip rotation F L^2/2EI + M L/EI" [nodeDisp $tip 3] \
  [expr {($d - $M * $L ** 2 / (2.0 * $E * $I)) * 3.0 * $E * $I / $L ** 3 * $L ** 2 / (2.0 * $E * $I) + $M * $L / ($E * $I)}] $TOL
wipe

# ---------------------------------------------------------------- 3D, skew member
# axis along (1,2,2)/3 so that the transformation is exercised in full
set L 300.0; set E 200.0; set G 80.0; set A 50.0; set J 900.0; set Iy 1200.0; set Iz 400.0
set Py 2.0; set Pz -1.5; set T 30.0; set N 25.0
proc vscale {s v} { lmap x $v {expr {$s * $x}} }
proc vadd {a b} { lmap x $a y $b {expr {$x + $y}} }
proc dot {a b} { set s 0.0; foreach x $a y $b { set s [expr {$s + $x * $y}] }; return $s }
proc cross {a b} {
  lassign $a a1 a2 a3; lassign $b b1 b2 b3
  list [expr {$a2 * $b3 - $a3 * $b2}] [expr {$a3 * $b1 - $a1 * $b3}] [expr {$a1 * $b2 - $a2 * $b1}]
}
proc unit {a} { vscale [expr {1.0 / sqrt([dot $a $a])}] $a }
set ex [unit {1.0 2.0 2.0}]
set vecxz {0.0 0.0 1.0}
# OpenSees convention for geomTransf: y = vecxz x x, z = x x y
set ey [unit [cross $vecxz $ex]]
set ez [cross $ex $ey]

model basic -ndm 3 -ndf 6
for {set i 0} {$i <= $nEle} {incr i} { node [expr {$i + 1}] {*}[vscale [expr {$L * $i / $nEle}] $ex] }
fix 1 1 1 1 1 1 1
geomTransf Linear 1 {*}$vecxz
for {set i 1} {$i <= $nEle} {incr i} {
  element elasticBeamColumn $i $i [expr {$i + 1}] $A $E $G $J $Iy $Iz 1
}
set force [vadd [vadd [vscale $N $ex] [vscale $Py $ey]] [vscale $Pz $ez]]
set moment [vscale $T $ex]
timeSeries Linear 1
pattern Plain 1 1 { load $tip {*}$force {*}$moment }
constraints Transformation; numberer RCM; system UmfPack
test NormDispIncr 1e-12 5; algorithm Linear
integrator LoadControl 1.0
analysis Static
checkTrue "3D cantilever: analyze returns 0" [expr {[analyze 1] == 0}]
set u [list [nodeDisp $tip 1] [nodeDisp $tip 2] [nodeDisp $tip 3]]
set r [list [nodeDisp $tip 4] [nodeDisp $tip 5] [nodeDisp $tip 6]]
check "3D skew cantilever: local-y deflection Py L^3/(3 E Iz)" [dot $u $ey] [expr {$Py * $L ** 3 / (3.0 * $E * $Iz)}] $TOL
check "3D skew cantilever: local-z deflection Pz L^3/(3 E Iy)" [dot $u $ez] [expr {$Pz * $L ** 3 / (3.0 * $E * $Iy)}] $TOL
check "3D skew cantilever: axial N L/(E A)" [dot $u $ex] [expr {$N * $L / ($E * $A)}] $TOL
check "3D skew cantilever: twist T L/(G J)" [dot $r $ex] [expr {$T * $L / ($G * $J)}] $TOL
check "3D skew cantilever: rotation about z Py L^2/(2 E Iz)" [dot $r $ez] [expr {$Py * $L ** 2 / (2.0 * $E * $Iz)}] $TOL
check "3D skew cantilever: rotation about y -Pz L^2/(2 E Iy)" [dot $r $ey] [expr {-$Pz * $L ** 2 / (2.0 * $E * $Iy)}] $TOL
wipe
finish
