# SPDX-License-Identifier: MIT
# Stick-slip oscillator (hard case 4): a contactor of mass m pressed by its weight W on a
# fixed face and tied to the ground by a spring k (zeroLength, Elastic). Closed form (Coulomb-
# damped oscillator, e.g. Den Hartog): each half cycle the amplitude falls by 2 mu_k N/k, so
# 4 mu_k N/k per cycle, and the motion stops at |x| <= mu_s N/k.
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] lib contact.tcl]

set K 1.0e5
set m 1.0
set k 100.0
set g 9.81
set W [expr {$m*$g}]
set muS 0.3
set muK 0.3
set dt [expr {2*$::pi*sqrt($m/$K)/20}]

wipe
model basic -ndm 3 -ndf 3
node 1 -2 -2 0; node 2 2 -2 0; node 3 2 2 0; node 4 -2 2 0
node 5 0 0 0
node 6 0 0 0
foreach t {1 2 3 4 6} { fix $t 1 1 1 }
fix 5 0 1 0
mass 5 $m $m $m
element nodeToSurface 1 5 1 2 3 4 -K $K -e 0.2 -et 0.5 -mu_s $muS -mu_k $muK -masses $m 1e12
uniaxialMaterial Elastic 1 $k
element zeroLength 2 6 5 -mat 1 -dir 1
timeSeries Constant 1
pattern Plain 1 1 { load 5 0 0 [expr {-$W}] }
# Launch: a push of 0.01 s giving about 3 m/s.
timeSeries Constant 2
pattern Plain 2 2 { load 5 [expr {3.0*$m/0.01}] 0 0 }
constraints Plain; numberer Plain; system FullGeneral
test NormDispIncr 1e-12 50; algorithm Newton
integrator Newmark 0.5 0.25; analysis Transient
set failed [runUntil $dt 0.01]
remove loadPattern 2

# Record the extremes of x (turning points: the velocity changes sign).
set extremes {}
set vPrev [nodeVel 5 1]
while {[getTime %.17g] < 5.0} {
  if {[analyze 1 $dt] != 0} { incr failed; break }
  set v [nodeVel 5 1]
  if {$v*$vPrev < 0} { lappend extremes [nodeDisp 5 1] }
  if {$v != 0} { set vPrev $v }
}
checkTrue "every step converged" [expr {$failed == 0}]
checkTrue "at least 4 turning points ([llength $extremes])" [expr {[llength $extremes] >= 4}]
set drop [expr {2*$muK*$W/$k}]
for {set i 1} {$i < [llength $extremes] && $i < 4} {incr i} {
  set a0 [expr {abs([lindex $extremes [expr {$i-1}]])}]
  set a1 [expr {abs([lindex $extremes $i])}]
  if {$a1 < $muS*$W/$k} break
  check "half cycle $i: amplitude falls by 2 mu_k N/k" [expr {$a0 - $a1}] $drop 2e-2
}
set xEnd [nodeDisp 5 1]
checkTrue "stopped within mu_s N/k: |x| = [format %.4f [expr {abs($xEnd)}]] <= [format %.4f [expr {$muS*$W/$k}]]" \
    [expr {abs($xEnd) <= $muS*$W/$k*(1 + 1e-6)}]
checkAbs "at rest" [nodeVel 5 1] 0.0 1e-3
finish
