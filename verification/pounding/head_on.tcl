# SPDX-License-Identifier: MIT
# Two masses colliding head-on through a nodeToSurface pair (hard case 1).
# Closed forms: momentum M1 v1 + M2 v2 is conserved; the exit/approach relative-speed ratio is the
# no-tension restitution e_eff(xi(e)) of a linear spring-dashpot (lib/contact.tcl), larger than
# e; the element's normal impulse equals M1 |dv1| (Newmark's trapezoid rule is exact for the
# impulse); the error in e_eff shrinks with the step (second-order Newmark).
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] lib contact.tcl]

set K 1.0e6      ;# contact stiffness
set M1 2.0       ;# contactor mass
set M2 3.0       ;# target mass (four nodes of M2/4)
set v0 1.0       ;# approach speed of the contactor
set gap0 0.01
set mred [expr {$M1*$M2/($M1+$M2)}]
set w [expr {sqrt($K/$mred)}]
set Tc [expr {$::pi/$w}]   ;# contact duration of the undamped pair

# Builds the pair, gives the contactor v0 towards the target with a short force pulse (free
# flight), then integrates through the impact with `n` steps per contact duration. Returns
# {v1 v2 v1' v2' impulse}.
proc impact {e n} {
  global K M1 M2 v0 gap0 Tc
  wipe
  model basic -ndm 3 -ndf 3
  node 1 -1 -1 0; node 2 1 -1 0; node 3 1 1 0; node 4 -1 1 0
  node 5 0 0 $gap0
  foreach n_ {1 2 3 4 5} { fix $n_ 1 1 0 }
  foreach n_ {1 2 3 4} { mass $n_ 0 0 [expr {$M2/4.0}] }
  mass 5 0 0 $M1
  element nodeToSurface 1 5 1 2 3 4 -K $K -e $e -masses $M1 $M2
  set tp 0.002
  set dt [expr {$Tc/$n}]
  set tp [expr {ceil($tp/$dt)*$dt}]
  timeSeries Constant 1
  pattern Plain 1 1 { load 5 0 0 [expr {-$M1*$v0/$tp}] }
  constraints Plain; numberer Plain; system FullGeneral
  test NormDispIncr 1e-12 50; algorithm Newton
  integrator Newmark 0.5 0.25; analysis Transient
  set failed [runUntil $dt $tp]
  remove loadPattern 1
  # Newmark averages the accelerations of a step's two ends: one more step ends the pulse.
  incr failed [runUntil $dt [expr {$tp + $dt}]]
  set v1 [nodeVel 5 3]; set v2 [nodeVel 1 3]
  incr failed [runUntil $dt [expr {$tp + 0.05}] {expr {[lindex [eleResponse 1 impulse] 0] > 0 && [lindex [eleResponse 1 gap] 0] > 0}}]
  # free flight after separation keeps the velocities; read them now
  return [list $v1 $v2 [nodeVel 5 3] [nodeVel 1 3] [lindex [eleResponse 1 impulse] 0] $failed]
}

foreach e {1.0 0.8 0.5} {
  set eEff [effectiveRestitution [dampingRatio $e]]
  set errors {}
  foreach n {20 40 80} {
    lassign [impact $e $n] v1 v2 u1 u2 impulse failed
    checkTrue "e=$e n=$n: every step converged" [expr {$failed == 0}]
    set p0 [expr {$M1*$v1 + $M2*$v2}]
    set p1 [expr {$M1*$u1 + $M2*$u2}]
    checkAbs "e=$e n=$n: momentum M1 v1 + M2 v2 conserved" $p1 $p0 [expr {1e-8*abs($p0)}]
    set ratio [expr {-($u1 - $u2)/($v1 - $v2)}]
    lappend errors [expr {abs($ratio - $eEff)}]
    # Tolerance: the O((w dt)^2) error of Newmark's trapezoidal rule (constant 1/2), plus, with a
    # dashpot, the force jump C v at first touch placed anywhere within a step: an impulse error
    # up to C v dt / 2 per jump, i.e. xi w dt in the speed ratio.
    set wdt [expr {$w*$Tc/$n}]
    set xi [dampingRatio $e]
    checkAbs "e=$e n=$n: exit ratio = no-tension e_eff [format %.5f $eEff]" $ratio $eEff \
        [expr {0.5*$wdt*$wdt + $xi*$wdt}]
    check "e=$e n=$n: normal impulse = M1 |dv1|" $impulse [expr {$M1*abs($u1 - $v1)}] 1e-8
  }
  checkTrue "e=$e: error at n=80 below error at n=20 ([join $errors {, }])" \
      [expr {[lindex $errors 2] < [lindex $errors 0]}]
  if {$e < 1.0} {
    checkTrue "e=$e: no-tension restitution [format %.4f $eEff] exceeds e" [expr {$eEff > $e}]
  }
}
finish
