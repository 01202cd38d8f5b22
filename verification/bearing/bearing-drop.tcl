# SPDX-License-Identifier: MIT
# A girder end on one yoshidaBearing with -afterFailure drop: the bearing carries the girder's
# weight W = M g, is sheared past its failure strain by an imposed longitudinal motion at constant
# speed, ruptures, and the girder end (mass M) falls by the bearing's height h onto the seat, comes
# to rest there and slides on with Coulomb friction while the motion goes on.
#
# Closed forms checked (the script's own):
#  1. failure at the imposed displacement 3 Tr, i.e. at time 3 Tr / v;
#  2. at rest on the seat node 2 stands at -(h + W/Ks) (seat spring Ks carries W);
#  3. sliding at constant speed: the seat's friction force is mu_k N = mu_k W, opposite to the
#     motion, and the element's longitudinal force at node 2 is +mu_k W;
#  4. the seat's normal force is W.
# Mass-proportional Rayleigh damping (alphaM) settles the vertical bounce on the seat: the decay
# rate is alphaM / 2 = 10 1/s, so 2 s after the landing the bounce has decayed by e^-20 (2e-9).
source [file join [file dirname [info script]] .. lib check.tcl]

set g 9.81
set M 200.0                  ;# t, girder mass on the bearing
set W [expr {$M * $g}]       ;# kN
set Tr 0.2                   ;# m
set Kv 1.0e6                 ;# kN/m
set h 0.15                   ;# m, bearing height (rubber, steel plates, sole plate)
set Ks 4.0e5                 ;# kN/m, seat
set muS 0.6
set muK 0.4
set v 0.5                    ;# m/s, imposed longitudinal speed of node 2
set dt 0.001
set tEnd 4.0
set TOL 1e-6

wipe
model basic -ndm 3 -ndf 6
node 1 0.0 0.0 0.0
node 2 0.0 0.0 0.0 -mass $M $M $M 0.0 0.0 0.0
fix 1 1 1 1 1 1 1
fix 2 0 0 0 1 1 1
biaxialMaterial Yoshida 1 150.0 0.012 2.0 0.0 0.0 1.0 0.0
element yoshidaBearing 1 1 2 1 -Tr $Tr -Kv $Kv -afterFailure drop $h -seat $Ks $muS $muK

# Gravity on the intact bearing (static), then held constant.
timeSeries Linear 1
pattern Plain 1 1 { load 2 0.0 0.0 [expr {-$W}] 0.0 0.0 0.0 }
constraints Transformation
numberer Plain
system BandGeneral
test NormDispIncr 1e-10 20
algorithm Newton
integrator LoadControl 0.1
analysis Static
checkTrue "gravity on the intact bearing converges" [expr {[analyze 10] == 0}]
check "intact bearing compressed by W/Kv" [nodeDisp 2 3] [expr {-$W / $Kv}] $TOL
loadConst -time 0.0

# Longitudinal motion u_x = v t of node 2 (global X = local y of the bearing).
timeSeries Linear 2 -factor $v
pattern Plain 2 2 { sp 2 1 1.0 }
rayleigh 20.0 0.0 0.0 0.0
wipeAnalysis
constraints Transformation
numberer Plain
system BandGeneral
test NormDispIncr 1e-10 30
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient

set failedSteps 0
set landed -1.0
set nSteps [expr {int(round($tEnd / $dt))}]
for {set i 0} {$i < $nSteps} {incr i} {
  if {[analyze 1 $dt] != 0} { incr failedSteps }
  if {$landed < 0 && [eleResponse 1 seatGap] < 0.0} { set landed [getTime] }
}
checkAbs "every transient step converged (failed steps)" $failedSteps 0 0
check "failure at u = 3 Tr, time 3 Tr / v" [eleResponse 1 failureTime] [expr {3.0 * $Tr / $v}] 1e-9
checkTrue "the bearing has dropped" [expr {[eleResponse 1 dropped] == 1.0}]
checkTrue "the girder end landed on the seat (at t = $landed s) at least 2 s before the end" \
  [expr {$landed > 0.0 && $landed < $tEnd - 2.0}]
check "girder end at rest on the seat at -(h + W/Ks)" [nodeDisp 2 3] [expr {-($h + $W / $Ks)}] $TOL
checkAbs "... and at rest vertically (velocity, m/s)" [nodeVel 2 3] 0.0 1e-8
lassign [eleResponse 1 seatForce] N Ft1 Ft2
check "seat normal force N = W" $N $W $TOL
checkTrue "sliding (seatStatus 2)" [expr {[eleResponse 1 seatStatus] == 2.0}]
check "friction force on the girder end -mu_k W (against the motion)" $Ft1 [expr {-$muK * $W}] $TOL
checkAbs "no transverse friction force" $Ft2 0.0 [expr {1e-9 * $W}]
check "element force at node 2 along X: +mu_k W" [lindex [eleResponse 1 force] 6] [expr {$muK * $W}] $TOL
check "element force at node 2 along Z: the seat carries W" [lindex [eleResponse 1 force] 8] [expr {-$W}] $TOL
wipe
finish
