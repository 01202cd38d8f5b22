# SPDX-License-Identifier: MIT
# Yoshida bi-axial bearing driven through the whole program: imposed displacements on a
# yoshidaBearing with coincident nodes (local y = global X, local z = global Y).
#
# Closed forms:
#  1. monotonic, no back force, n = 2: F = Y tanh(U/U0), here along an oblique direction;
#  2. circular orbit U = R (cos t, sin t), no back force: |F| settles at Y rho and F is phi ahead
#     of U in the direction of motion, where rho = (R/U0) cos(phi), rho^n = sin(phi)
#     (R/U0 = 3, n = 2: rho = 0.97262, phi = 1.2406 rad); work per revolution 2 pi R Y rho^(n+1);
#  3. damage flag 2 (failed) at exactly |U| = 3 Tr in an oblique direction, 1 at 2.5 Tr.
# Tolerance: the material's default sub-step (0.02 U0) gives force errors below 1 % of Y
# (materials/tests/YoshidaBearingMaterialTest.StepSizeStudyShowsFirstOrder).
source [file join [file dirname [info script]] .. lib check.tcl]

set TOL_INTEGRATION 0.01
set pi [expr {acos(-1.0)}]
set Y0 150.0
set U0 0.012
set Tr 0.2

# Builds the bearing and a displacement path (lists of x and y, one point per pseudo-time step).
proc runPath {xs ys body} {
  global Y0 U0 Tr
  wipe
  model basic -ndm 3 -ndf 6
  node 1 0.0 0.0 0.0
  node 2 0.0 0.0 0.0
  fix 1 1 1 1 1 1 1
  fix 2 0 0 0 1 1 1   ;# vertical left free (axial spring): the system needs a free dof
  biaxialMaterial Yoshida 1 $Y0 $U0 2.0 0.0 0.0 1.0 0.0
  element yoshidaBearing 1 1 2 1 -Tr $Tr -Kv 1.0e6
  timeSeries Path 1 -dt 1.0 -values [concat 0.0 $xs] -useLast
  timeSeries Path 2 -dt 1.0 -values [concat 0.0 $ys] -useLast
  pattern Plain 1 1 { sp 2 1 1.0 }
  pattern Plain 2 2 { sp 2 2 1.0 }
  constraints Transformation
  numberer Plain
  system BandGeneral
  test NormDispIncr 1e-10 20
  algorithm Newton
  integrator LoadControl 1.0
  analysis Static
  set n [llength $xs]
  for {set i 0} {$i < $n} {incr i} {
    if {[analyze 1] != 0} { error "analyze failed at step $i" }
    uplevel 1 [list set step $i]
    uplevel 1 $body
  }
}

# 1. monotonic along (0.6, 0.8) up to 3 U0
set xs {}; set ys {}
for {set i 1} {$i <= 300} {incr i} {
  set u [expr {3.0 * $U0 * $i / 300.0}]
  lappend xs [expr {0.6 * $u}]; lappend ys [expr {0.8 * $u}]
}
set checkpoints {100 200 299}
runPath $xs $ys {
  if {$step in $checkpoints} {
    set q [eleResponse 1 basicForce]
    set u [expr {3.0 * $U0 * ($step + 1) / 300.0}]
    set f [expr {hypot([lindex $q 1], [lindex $q 2])}]
    check "monotonic n=2: |F| = Y tanh(U/U0) at U/U0 = [format %.2f [expr {$u / $U0}]]" \
        $f [expr {$Y0 * tanh($u / $U0)}] $TOL_INTEGRATION
  }
}

# 2. circular orbit, R = 3 U0: radial ramp, then 4 revolutions of 720 steps; the last is measured
proc orbitClosedForm {r n} {
  set lo 0.0; set hi [expr {acos(-1.0) / 2}]
  for {set i 0} {$i < 200} {incr i} {
    set mid [expr {0.5 * ($lo + $hi)}]
    if {pow($r * cos($mid), $n) - sin($mid) > 0} { set lo $mid } else { set hi $mid }
  }
  return [list [expr {$r * cos($lo)}] $lo]
}
lassign [orbitClosedForm 3.0 2.0] rho phi
check "orbit closed form rho" $rho 0.97262 1e-5
check "orbit closed form phi" $phi 1.2406 1e-4
set R [expr {3.0 * $U0}]
set perRev 720
set xs {}; set ys {}
for {set i 1} {$i <= 100} {incr i} { lappend xs [expr {$R * $i / 100.0}]; lappend ys 0.0 }
for {set i 1} {$i <= 4 * $perRev} {incr i} {
  set t [expr {2 * $pi * $i / $perRev}]
  lappend xs [expr {$R * cos($t)}]; lappend ys [expr {$R * sin($t)}]
}
set fmin 1e300; set fmax 0.0; set work 0.0; set prev {}
set firstMeasured [expr {100 + 3 * $perRev}]
runPath $xs $ys {
  if {$step >= $firstMeasured - 1} {
    set q [eleResponse 1 basicForce]
    set fx [lindex $q 1]; set fy [lindex $q 2]
    set ux [nodeDisp 2 1]; set uy [nodeDisp 2 2]
    set e [lindex [eleResponse 1 dissipatedEnergy] 0]
    if {$step == $firstMeasured - 1} { set e0 $e }
    if {$prev ne {}} {
      lassign $prev pfx pfy pux puy
      set work [expr {$work + 0.5 * (($fx + $pfx) * ($ux - $pux) + ($fy + $pfy) * ($uy - $puy))}]
      set f [expr {hypot($fx, $fy)}]
      set fmin [expr {min($fmin, $f)}]; set fmax [expr {max($fmax, $f)}]
      set angle [expr {atan2($ux * $fy - $uy * $fx, $ux * $fx + $uy * $fy)}]
    }
    set prev [list $fx $fy $ux $uy]
  }
}
check "orbit: smallest |F| over the 4th revolution = Y rho" $fmin [expr {$Y0 * $rho}] $TOL_INTEGRATION
check "orbit: largest |F| over the 4th revolution = Y rho" $fmax [expr {$Y0 * $rho}] $TOL_INTEGRATION
check "orbit: F ahead of U by phi" $angle $phi $TOL_INTEGRATION
set wExact [expr {2 * $pi * $R * $Y0 * pow($rho, 3)}]
check "orbit: work per revolution 2 pi R Y rho^3" $work $wExact $TOL_INTEGRATION
check "orbit: dissipatedEnergy response over the revolution" [expr {$e - $e0}] $wExact $TOL_INTEGRATION

# 3. damage flags in the direction (cos 0.7, sin 0.7)
set xs {}; set ys {}
foreach g {1.0 2.4 2.5 2.0 3.0 1.0} {
  lappend xs [expr {$g * $Tr * cos(0.7)}]; lappend ys [expr {$g * $Tr * sin(0.7)}]
}
set expectedDamage {0 0 1 1 2 2}
set damage {}
runPath $xs $ys { lappend damage [expr {int([lindex [eleResponse 1 damage] 0])}] }
checkTrue "damage flags 0,0,1,1,2,2 along strains 1, 2.4, 2.5, 2.0, 3.0, 1.0 (got $damage)" \
    [expr {$damage eq $expectedDamage}]
checkAbs "failure recorded at the step with |U| = 3 Tr (pseudo-time 5)" \
    [lindex [eleResponse 1 failureTime] 0] 5.0 1e-12
wipe
finish
