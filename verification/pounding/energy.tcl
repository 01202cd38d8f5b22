# SPDX-License-Identifier: MIT
# Energy balance of a head-on impact (hard case 6): kinetic + strain + dissipated = work
# done. After the pulse that launches the contactor no external work is done and after separation
# no strain energy remains, so KE_before = KE_after + dissipated, where `dissipatedEnergy` is the
# element's dashpot work (trapezoid rule over the steps) plus friction work. A stiff contact hit
# with a large step must still converge (sub-stepping allowed) and never gain energy.
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] lib contact.tcl]

set M1 2.0
set M2 3.0
set v0 1.0

# Returns {KE_before KE_after dissipated failed}.
proc impact {K e dt} {
  global M1 M2 v0
  wipe
  model basic -ndm 3 -ndf 3
  node 1 -1 -1 0; node 2 1 -1 0; node 3 1 1 0; node 4 -1 1 0
  node 5 0 0 0.01
  foreach n_ {1 2 3 4 5} { fix $n_ 1 1 0 }
  foreach n_ {1 2 3 4} { mass $n_ 0 0 [expr {$M2/4.0}] }
  mass 5 0 0 $M1
  element nodeToSurface 1 5 1 2 3 4 -K $K -e $e -masses $M1 $M2
  set tp [expr {max(0.002, ceil(0.002/$dt)*$dt)}]
  timeSeries Constant 1
  pattern Plain 1 1 { load 5 0 0 [expr {-$M1*$v0/$tp}] }
  constraints Plain; numberer Plain; system FullGeneral
  test NormDispIncr 1e-12 50; algorithm Newton
  integrator Newmark 0.5 0.25; analysis Transient -numSubLevels 4 -numSubSteps 4
  set failed [runUntil $dt $tp]
  remove loadPattern 1
  incr failed [runUntil $dt [expr {$tp + $dt}]]
  set ke0 [expr {0.5*$M1*pow([nodeVel 5 3], 2) + 0.5*$M2*pow([nodeVel 1 3], 2)}]
  incr failed [runUntil $dt [expr {$tp + 0.1}] {expr {[lindex [eleResponse 1 impulse] 0] > 0 && [lindex [eleResponse 1 gap] 0] > 0}}]
  set ke1 [expr {0.5*$M1*pow([nodeVel 5 3], 2) + 0.5*$M2*pow([nodeVel 1 3], 2)}]
  return [list $ke0 $ke1 [lindex [eleResponse 1 dissipatedEnergy] 0] $failed]
}

set mred [expr {$M1*$M2/($M1+$M2)}]
# 1. Energy balance with dashpots, steps of Tc/n.
foreach e {0.8 0.5} {
  foreach n {40 160} {
    set K 1.0e6
    set Tc [expr {$::pi*sqrt($mred/$K)}]
    lassign [impact $K $e [expr {$Tc/$n}]] ke0 ke1 diss failed
    checkTrue "e=$e n=$n: converged" [expr {$failed == 0}]
    # The dashpot power jumps at first touch (C v^2); the trapezoid rule misplaces it by up to
    # half a step: error <= C v0^2 dt / 2 = 2 xi w dt KE_rel, with KE_rel = mred v0^2 / 2.
    set xi [dampingRatio $e]
    set wdt [expr {$::pi/$n}]
    set keRel [expr {0.5*$mred*$v0*$v0}]
    checkAbs "e=$e n=$n: KE_before = KE_after + dissipated" [expr {$ke1 + $diss}] $ke0 \
        [expr {(2*$xi*$wdt + 0.5*$wdt*$wdt)*$keRel}]
    set eEff [effectiveRestitution $xi]
    checkAbs "e=$e n=$n: dissipated = (1 - e_eff^2) KE_rel" $diss [expr {(1 - $eEff*$eEff)*$keRel}] \
        [expr {(2*$xi*$wdt + 0.5*$wdt*$wdt)*$keRel}]
  }
}

# 2. Stiff contact, large steps (up to 10 contact durations per step): converges, never gains.
set K 1.0e10
set Tc [expr {$::pi*sqrt($mred/$K)}]
foreach ratio {1 3 10} {
  foreach e {1.0 0.5} {
    lassign [impact $K $e [expr {$ratio*$Tc}]] ke0 ke1 diss failed
    checkTrue "stiff K, dt = $ratio Tc, e=$e: converged" [expr {$failed == 0}]
    checkTrue "stiff K, dt = $ratio Tc, e=$e: energy does not grow (KE after [format %.6g $ke1] <= before [format %.6g $ke0])" \
        [expr {$ke1 <= $ke0*(1 + 1e-9)}]
  }
}
finish
