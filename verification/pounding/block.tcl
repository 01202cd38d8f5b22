# SPDX-License-Identifier: MIT
# A block on a plane (hard case 3): contactor node of mass m pressed by its weight W on a
# fixed face. Closed forms (Coulomb friction): under a ramp P = r t it stays stuck until
# P = mu_s W, then slides with acceleration (P - mu_k W)/m, so
# v(t) = [r (t^2 - ts^2)/2 - mu_k W (t - ts)] / m with ts = mu_s W / r; launched with speed v0 it
# stops after sliding v0^2 / (2 mu_k g).
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] lib contact.tcl]

set K 1.0e5
set m 1.0
set g 9.81
set W [expr {$m*$g}]
set muS 0.4
set muK 0.3
set T [expr {2*$::pi*sqrt($m/$K)}]
set dt [expr {$T/20}]

proc block {} {
  global K m W muS muK
  wipe
  model basic -ndm 3 -ndf 3
  node 1 -2 -2 0; node 2 2 -2 0; node 3 2 2 0; node 4 -2 2 0
  node 5 -1 0 0
  foreach t {1 2 3 4} { fix $t 1 1 1 }
  fix 5 0 1 0
  mass 5 $m $m $m
  # e = 0.2 damps the normal bounce when the weight is applied; et = 0.5 damps the stick spring.
  element nodeToSurface 1 5 1 2 3 4 -K $K -e 0.2 -et 0.5 -mu_s $muS -mu_k $muK -masses $m 1e12
  timeSeries Constant 1
  pattern Plain 1 1 { load 5 0 0 [expr {-$W}] }
  constraints Plain; numberer Plain; system FullGeneral
  test NormDispIncr 1e-12 50; algorithm Newton
  integrator Newmark 0.5 0.25; analysis Transient
}

# 1. Ramp.
set r 10.0
block
timeSeries Linear 2
pattern Plain 2 2 { load 5 $r 0 0 }
set ts -1
set failed [runUntil $dt 0.8 {
  if {$::ts < 0 && [eleResponse 1 status] == 2} { set ::ts [getTime %.17g] }
  expr 0
}]
checkTrue "ramp: every step converged" [expr {$failed == 0}]
checkAbs "ramp: sliding starts at P = mu_s W" [expr {$r*$ts}] [expr {$muS*$W}] [expr {2*$r*$dt}]
set t [getTime %.17g]
set t0 [expr {$muS*$W/$r}]
set v [expr {($r*($t*$t - $t0*$t0)/2 - $muK*$W*($t - $t0))/$m}]
check "ramp: v(t) from a = (P - mu_k W)/m" [nodeVel 5 1] $v 1e-2

# 2. Launch with a short push, then free sliding to rest.
block
set tp 0.01
timeSeries Constant 3
pattern Plain 3 3 { load 5 [expr {2.0*$m/$tp}] 0 0 }
set failed [runUntil $dt $tp]
remove loadPattern 3
incr failed [runUntil $dt [expr {$tp + $dt}]]
set v0 [nodeVel 5 1]
set x0 [nodeDisp 5 1]
incr failed [runUntil $dt 2.0]
checkTrue "stop: every step converged" [expr {$failed == 0}]
check "stop: sliding distance v0^2/(2 mu_k g)" [expr {[nodeDisp 5 1] - $x0}] [expr {$v0*$v0/(2*$muK*$g)}] 1e-2
checkAbs "stop: at rest" [nodeVel 5 1] 0.0 1e-3
finish
