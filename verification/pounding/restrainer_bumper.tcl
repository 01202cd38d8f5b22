# SPDX-License-Identifier: MIT
# Restrainer and bumper gap springs (hard case 8): force-displacement through their
# clearances in both directions and yielding, through the material tester and through a
# zeroLength element between two girder ends under imposed displacements.
# Closed forms: restrainer F = 0 for u <= gap, k (u - gap) beyond, Fy + b k (u - gap - Fy/k) once
# yielded, elastic unloading with slope k to zero force at the permanent elongation; bumper the
# same in closing (negative force).
source [file join [file dirname [info script]] .. lib check.tcl]

set k 2000.0
set gap 0.05
set Fy 60.0
set b 0.1
set uy [expr {$Fy/$k}]
wipe
model basic -ndm 1 -ndf 1
uniaxialMaterial Restrainer 1 $k $gap -Fy $Fy -b $b
uniaxialMaterial Bumper 2 $k $gap -Fy $Fy -b $b

proc stressAt {u} { setStrain $u; return [getStress] }

testUniaxialMaterial 1
checkAbs "restrainer: closing, no force" [stressAt -0.2] 0.0 0.0
checkAbs "restrainer: opening inside the clearance, no force" [stressAt 0.04] 0.0 0.0
checkAbs "restrainer: k (u - gap)" [stressAt 0.06] [expr {$k*0.01}] 1e-9
set u1 [expr {$gap + 0.1}]
set f1 [expr {$Fy + $b*$k*(0.1 - $uy)}]
checkAbs "restrainer: yielded, Fy + b k (u - gap - uy)" [stressAt $u1] $f1 1e-9
set ep [expr {0.1 - $f1/$k}]
checkAbs "restrainer: elastic unloading k" [stressAt [expr {$u1 - 0.01}]] [expr {$f1 - $k*0.01}] 1e-9
checkAbs "restrainer: slack below gap + permanent elongation" [stressAt [expr {$gap + 0.5*$ep}]] 0.0 0.0
checkAbs "restrainer: reloads at gap + permanent elongation" [stressAt [expr {$gap + $ep + 0.001}]] [expr {$k*0.001}] 1e-9

testUniaxialMaterial 2
checkAbs "bumper: opening, no force" [stressAt 0.2] 0.0 0.0
checkAbs "bumper: closing inside the clearance, no force" [stressAt -0.04] 0.0 0.0
checkAbs "bumper: -k (closing - gap)" [stressAt -0.06] [expr {-$k*0.01}] 1e-9
checkAbs "bumper: crushed, -(Fy + b k (closing - gap - uy))" [stressAt [expr {-$gap - 0.1}]] [expr {-$f1}] 1e-9
checkAbs "bumper: clearance grown by the permanent crush" [stressAt [expr {-$gap - 0.5*$ep}]] 0.0 0.0

# zeroLength between girder ends 1 and 2 with restrainer (tension) and bumper (compression) in
# parallel along x; node 2 driven by imposed displacements (static, displacement control by sp).
wipe
model basic -ndm 3 -ndf 3
node 1 0 0 0; node 2 0 0 0
fix 1 1 1 1; fix 2 0 1 1
uniaxialMaterial Restrainer 1 $k $gap -Fy $Fy -b $b
uniaxialMaterial Bumper 2 [expr {2*$k}] 0.02
element zeroLength 1 1 2 -mat 1 2 -dir 1 1
timeSeries Linear 1
pattern Plain 1 1 { sp 2 1 1.0 }
constraints Transformation; numberer Plain; system FullGeneral
test NormDispIncr 1e-12 20; algorithm Newton
integrator LoadControl 0.01; analysis Static
# Path: open to 0.15 (restrainer yields), close to -0.05 (bumper engages past 0.02), back to 0.
set path {}
set failed 0
foreach {target} {0.15 -0.05 0.0} {
  set u [nodeDisp 2 1]
  set n [expr {int(round(abs($target - $u)/0.005))}]
  integrator LoadControl [expr {($target - $u)/$n}]
  for {set i 0} {$i < $n} {incr i} {
    if {[analyze 1] != 0} { incr failed }
    lappend path [nodeDisp 2 1] [lindex [eleForce 1] 3]
  }
}
checkTrue "zeroLength path converged" [expr {$failed == 0}]
proc forceAt {u} {
  foreach {x f} $::path { if {abs($x - $u) < 1e-9} { set out $f } }
  return $out
}
set ep [expr {0.1 - $f1/$k}]
checkAbs "zeroLength at 0.15: yielded restrainer" [forceAt 0.15] $f1 1e-6
checkAbs "zeroLength at 0.13 (unloading): k slope from the peak" [forceAt 0.13] [expr {$f1 - $k*0.02}] 1e-6
checkAbs "zeroLength at 0.0: both slack" [forceAt 0.0] 0.0 1e-9
checkAbs "zeroLength at -0.05: bumper 2k (0.05 - 0.02)" [forceAt -0.05] [expr {-2*$k*0.03}] 1e-6
finish
