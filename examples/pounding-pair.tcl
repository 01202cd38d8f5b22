# SPDX-License-Identifier: MIT
# Two girder ends pounding once through one contact pair (units kN, m, s, t).
# Prints the velocities before and after the impact, the measured coefficient of restitution, and
# the closed form for the Kelvin contact law (spring K + dashpot that cannot pull) next to it.
set M1 500.0    ;# t, mass of the moving girder (the contactor node)
set M2 800.0    ;# t, mass of the girder it hits (four face nodes of M2/4)
set K  2.0e7    ;# kN/m, contact spring, about E A / L of a girder
set e  0.65     ;# coefficient of restitution given to the contact dashpot
set v0 0.5      ;# m/s, approach speed
set pi [expr {acos(-1.0)}]
model basic -ndm 3 -ndf 3                          ;# 3D, translations only
# Target face in the plane x = 0, corners ordered so the normal (b-a)x(d-a) points to -x
node 1 0 -1 -1; node 2 0 -1 1; node 3 0 1 1; node 4 0 1 -1
node 5 -0.01 0 0                                   ;# contactor, 10 mm in front of the face
foreach n {1 2 3 4 5} { fix $n 0 1 1 }             ;# only longitudinal (x) motion
foreach n {1 2 3 4} { mass $n [expr {$M2/4}] 0 0 }
mass 5 $M1 0 0
# The pounding pair: spring K, dashpot tuned to e for the two masses
element nodeToSurface 1 5 1 2 3 4 -K $K -e $e -masses $M1 $M2
set Tc [expr {$pi*sqrt($M1*$M2/($M1+$M2)/$K)}]   ;# contact duration without damping
set dt [expr {$Tc/100.0}]                         ;# 100 steps per contact
constraints Plain; numberer Plain; system FullGeneral
test NormDispIncr 1e-12 50; algorithm Newton
integrator Newmark 0.5 0.25; analysis Transient
# Speed up the contactor with a short push M1 v0 / tp over 5 steps (free flight, no contact yet)
timeSeries Constant 1
pattern Plain 1 1 { load 5 [expr {$M1*$v0/(5*$dt)}] 0 0 }
if {[analyze 5 $dt] != 0} { puts "push failed"; exit 1 }
remove loadPattern 1
if {[analyze 1 $dt] != 0} { puts "push failed"; exit 1 }   ;# Newmark averages: one more step ends the push
set v1 [nodeVel 5 1]; set v2 [nodeVel 1 1]       ;# velocities before the impact
# Integrate until the pair has touched and opened again (impulse > 0 and gap > 0)
while {!([lindex [eleResponse 1 impulse] 0] > 0 && [lindex [eleResponse 1 gap] 0] > 0)} {
  if {[analyze 1 $dt] != 0 || [getTime] > 1.0} { puts "impact analysis failed"; exit 1 }
}
set u1 [nodeVel 5 1]; set u2 [nodeVel 1 1]       ;# velocities after separation
set eModel [expr {-($u1 - $u2)/($v1 - $v2)}]     ;# measured restitution
# Closed form (contact/NormalLaw.h): damping ratio of the dashpot, then the effective restitution
# of a spring-dashpot whose force may not pull (contact ends when the force reaches zero)
set l [expr {log($e)}]
set xi [expr {-$l/sqrt($pi*$pi + $l*$l)}]
set r [expr {sqrt(1 - $xi*$xi)}]
set phase [expr {$pi - atan2(2*$xi*$r, 1 - 2*$xi*$xi)}]
set eEff [expr {exp(-$xi*$phase/$r)*($xi/$r*sin($phase) - cos($phase))}]
puts [format "before impact: girder 1 %.4f m/s, girder 2 %.4f m/s" $v1 $v2]
puts [format "after impact:  girder 1 %.4f m/s, girder 2 %.4f m/s" $u1 $u2]
puts [format "momentum before %.3f, after %.3f t m/s" [expr {$M1*$v1 + $M2*$v2}] [expr {$M1*$u1 + $M2*$u2}]]
puts [format "dashpot damping ratio xi = %.4f for e = %.2f" $xi $e]
puts [format "restitution: model %.4f, closed form (no-tension Kelvin) %.4f, given e %.2f" $eModel $eEff $e]
# Sanity check: within 1 % of the closed form (Newmark's error at 100 steps per contact is smaller)
if {abs($eModel - $eEff) > 0.01*$eEff} { puts "FAILED: restitution off the closed form"; exit 1 }
