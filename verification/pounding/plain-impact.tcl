# SPDX-License-Identifier: MIT
# A plain impact as an engineer writes it: a 2 t contactor 0.01 m above a free 3 t face (four
# nodes), pushed down by 10 kN, K 1e6 and e 0.5 (dashpot), steps of 0.01 s, three times longer
# than the contact (pi sqrt(m/K) = 3.4 ms), no contact stepping. The Kelvin dashpot force jumps
# from 0 to C |gdot| at first touch, and with C dt / (2 m) > 1 no end state of the impact step
# lies on either side of the jump: plain Newton cycled there for ever. The analysis holds the
# pair's branches after two iterations (Element::HeldStatus) and takes the end state within
# the jump (the spring alone, Filippov's selection). Checked, for every algorithm and with HHT
# and contact stepping:
# - every step converges, in at most 10 iterations with Newton (the default algorithm);
# - momentum: the contact force is internal, and the trapezoid rule of the velocities gives
#   exactly M1 v5 + M2 v1 = F (t - (1 - gamma) dt) for the constant force F (closed form: the
#   analysis starts from zero acceleration, as OpenSees' does, and v1 = dt (gamma a1 + (1 -
#   gamma) a0); gamma = 1/2 for Newmark, 3/2 - alpha for HHT);
# - energy: the kinetic energy never exceeds the work of F (the pair may dissipate, never add).
source [file join [file dirname [info script]] .. lib check.tcl]

set M1 2.0
set M2 3.0
set F -10.0

proc run {algorithm integrator stepping} {
  global M1 M2 F
  set gamma [expr {[lindex $integrator 0] eq "HHT" ? 1.5 - [lindex $integrator 1] : 0.5}]
  wipe
  model basic -ndm 3 -ndf 3
  node 1 -1 -1 0; node 2 1 -1 0; node 3 1 1 0; node 4 -1 1 0
  node 5 0 0 0.01
  foreach n {1 2 3 4} { fix $n 1 1 0; mass $n 0 0 [expr {$M2/4.0}] }
  fix 5 1 1 0; mass 5 0 0 $M1
  element nodeToSurface 1 5 1 2 3 4 -K 1e6 -e 0.5 -masses $M1 $M2
  timeSeries Constant 1
  pattern Plain 1 1 { load 5 0 0 $F }
  constraints Plain; numberer Plain; system FullGeneral
  test NormDispIncr 1e-10 50
  algorithm {*}$algorithm
  integrator {*}$integrator
  analysis Transient
  if {$stepping} { contactStepping }
  set worst 0; set momentum 0.0; set gain 0.0; set closed 0
  for {set i 0} {$i < 100} {incr i} {
    if {[analyze 1 0.01] != 0} { return [list fail [getTime] $worst $momentum $gain $closed] }
    if {!$stepping && [testIter] > $worst} { set worst [testIter] }
    set t [getTime]
    set p [expr {$M1*[nodeVel 5 3] + $M2*[nodeVel 1 3]}]
    set momentum [expr {max($momentum, abs($p - $F*($t - (1.0 - $gamma)*0.01)) / abs($F*$t))}]
    set ke [expr {0.5*$M1*[nodeVel 5 3]**2 + 0.5*$M2*[nodeVel 1 3]**2}]
    set work [expr {$F*[nodeDisp 5 3]}]
    set gain [expr {max($gain, ($ke - $work) / $work)}]
    if {[eleResponse 1 status] != 0} { incr closed }
  }
  return [list ok [getTime] $worst $momentum $gain $closed]
}

foreach algorithm {Newton ModifiedNewton NewtonLineSearch KrylovNewton} {
  foreach integrator {{Newmark 0.5 0.25} {HHT 0.9}} {
    foreach stepping {0 1} {
      lassign [run $algorithm $integrator $stepping] status t worst momentum gain closed
      set name "$algorithm, $integrator, contact stepping $stepping"
      checkTrue "$name: 100 steps of 0.01 s complete (stopped at $t)" [expr {$status eq "ok"}]
      checkTrue "$name: the pair touched in some step ($closed)" [expr {$closed > 0}]
      checkAbs "$name: momentum M1 v5 + M2 v1 = F (t - (1 - gamma) dt) (relative)" $momentum 0.0 1e-9
      checkTrue "$name: no energy gained (kinetic - work of F)/work = $gain" [expr {$gain < 1e-9}]
      if {$algorithm eq "Newton" && !$stepping} {
        checkTrue "$name: at most 10 iterations in a step ($worst)" [expr {$worst <= 10}]
      }
    }
  }
}

# Jankowski's law in a step 45 times longer than the impact (k_h 1.263e10 kN/m^1.5, 1 t on a free
# 1 t face, 1 m/s, dt 0.01 s): his damping c delta^(1/4) rises from the touch with infinite slope,
# and the end state of the impact step needs the damping force at a penetration of about 1e-14 m,
# out of Newton's reach; its iterates jumped across the face until the step failed (code -3).
# The pair holds the spring alone once they cross the face (checkHeldStatus's
# selection at Kelvin's dashpot jump): the run completes. Only completion is checked: a step
# that does not resolve the impact cannot give its restitution (hard-impacts.tcl reports it).
proc jankowskiInOneStep {} {
  wipe
  model basic -ndm 3 -ndf 3
  node 1 -1 -1 0; node 2 1 -1 0; node 3 1 1 0; node 4 -1 1 0
  foreach n {1 2 3 4} { fix $n 1 1 0; mass $n 0 0 0.25 }
  node 5 0 0 0.0537; fix 5 1 1 0; mass 5 0 0 1.0
  element nodeToSurface 1 5 1 2 3 4 -law jankowski -K 1.263e10 -e 0.5 -masses 1.0 1.0
  constraints Plain; numberer Plain; system UmfPack
  test NormDispIncr 1e-8 25
  algorithm Newton; integrator Newmark 0.5 0.25; analysis Transient
  timeSeries Constant 1
  pattern Plain 1 1 { load 5 0 0 -50.0 }
  analyze 2 0.01
  remove loadPattern 1
  for {set i 0} {$i < 10} {incr i} {
    if {[analyze 1 0.01] != 0} { return [list fail [getTime]] }
  }
  return [list ok [getTime] [lindex [eleResponse 1 impulse] 0]]
}
lassign [jankowskiInOneStep] status t impulse
checkTrue "jankowski, k_h 1.263e10, dt 0.01: 10 steps after the approach complete (stopped at $t)" \
    [expr {$status eq "ok"}]
checkTrue "jankowski, k_h 1.263e10, dt 0.01: the pair gave an impulse ($impulse)" \
    [expr {$status eq "ok" && $impulse > 0.0}]
# Hertz's law in a step 340 times longer than the impact (k_h 3.994e12 kN/m^1.5, 1 t on a fixed
# face, 1 m/s: a contact of 2.9e-5 s; dt 0.01 s): the step's first iterate penetrates 1.3e-3 m
# and its end state about 4e-8 m, and Newton shrinks a delta^1.5 spring's penetration only to a
# third an iteration (12 iterations in that step before the pair asked for the step of Newton on
# its force, Element::newtonStepScale). Checked: the impact step takes at most 5 iterations, and
# its end state is the root of the step's own equation, m a(u) = k_h (-g(u))^1.5 (the contact
# force on the contactor) with Newmark's a(u) = 4 (u - u_n - h v_n) / h^2 - a_n, found here by
# bisection (an independent calculation): a longer Newton step changes the path, not the answer.
proc hertzInOneStep {} {
  set k 3.994e12; set h 0.01; set z0 0.0537
  wipe
  model basic -ndm 3 -ndf 3
  node 1 -1 -1 0; node 2 1 -1 0; node 3 1 1 0; node 4 -1 1 0
  foreach n {1 2 3 4} { fix $n 1 1 1 }
  node 5 0 0 $z0; fix 5 1 1 0; mass 5 0 0 1.0
  element nodeToSurface 1 5 1 2 3 4 -law hertz -K $k -masses 1.0 1e9
  constraints Plain; numberer Plain; system UmfPack
  test NormDispIncr 1e-8 25
  algorithm Newton; integrator Newmark 0.5 0.25; analysis Transient
  timeSeries Constant 1
  pattern Plain 1 1 { load 5 0 0 -50.0 }
  analyze 2 $h
  remove loadPattern 1
  for {set i 0} {$i < 10} {incr i} {
    set un [nodeDisp 5 3]; set vn [nodeVel 5 3]; set an [nodeAccel 5 3]
    if {[analyze 1 $h] != 0} { return [list fail [getTime]] }
    set u [nodeDisp 5 3]
    if {$z0 + $u < 0.0} {
      # m a(u) - N(u) increases with u: its root by bisection
      set lo [expr {-$z0 - 0.01}]; set hi [expr {-$z0}]
      for {set j 0} {$j < 200} {incr j} {
        set mid [expr {0.5*($lo + $hi)}]
        set acc [expr {4.0*($mid - $un - $h*$vn)/($h*$h) - $an}]
        set r [expr {1.0*$acc - $k*(-($z0 + $mid))**1.5}]
        if {$r > 0.0} { set hi $mid } else { set lo $mid }
      }
      return [list ok [getTime] [testIter] $u [expr {0.5*($lo + $hi)}]]
    }
  }
  return [list none [getTime]]
}
lassign [hertzInOneStep] status t iter u root
checkTrue "hertz, k_h 3.994e12, dt 0.01: the impact step completes and closes the pair ($status at $t)" \
    [expr {$status eq "ok"}]
if {$status eq "ok"} {
  checkTrue "hertz, k_h 3.994e12, dt 0.01: at most 5 iterations in the impact step ($iter)" \
      [expr {$iter <= 5}]
  checkAbs "hertz, k_h 3.994e12, dt 0.01: the end state is the root of the step's equation (m)" \
      $u $root 1e-8
}
finish
