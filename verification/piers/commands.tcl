# SPDX-License-Identifier: MIT
# Commands added for the piers: section Elastic / Aggregator, element zeroLengthSection,
# geomTransf Corotational (3D), -cMass on forceBeamColumn/dispBeamColumn. Bad input is a Tcl
# error with a message naming the argument (and nothing is created); good input builds a model
# whose response matches a closed form:
#  - zeroLengthSection over section Elastic: moment = EI * rotation (curvature), axial = EA eps;
#  - Aggregator adding a Vy spring: shear = k * relative displacement;
#  - a 3D forceBeamColumn (Corotational, -cMass) in series with a zeroLengthSection under a torque:
#    twist T L/GJ + T/GJ. (The consistent mass itself is checked in the unit tests.)
source [file join [file dirname [info script]] .. lib check.tcl]

proc fails {script pattern} {
  set code [catch {uplevel 1 $script} msg]
  return [expr {$code == 1 && [string match -nocase $pattern $msg]}]
}

# ------------------------------------------------------------------ 2D
wipe
model basic -ndm 2 -ndf 3
checkTrue "section Elastic: negative E rejected" [fails {section Elastic 1 -2.0e8 0.02 3e-4} "*E*positive*"]
checkTrue "section Elastic: missing Iz rejected" [fails {section Elastic 1 2.0e8 0.02} "*Iz*"]
checkTrue "section Elastic: G without alphaY rejected" [fails {section Elastic 1 2.0e8 0.02 3e-4 8e7} "*alphaY*"]
section Elastic 1 2.0e8 0.02 3.0e-4
checkTrue "section Elastic: duplicate tag rejected" [fails {section Elastic 1 2.0e8 0.02 3e-4} "*already exists*"]
uniaxialMaterial Elastic 5 1.0e5
checkTrue "Aggregator: unknown code rejected" [fails {section Aggregator 2 5 Qx} "*unknown resultant*"]
checkTrue "Aggregator: T in 2D rejected" [fails {section Aggregator 2 5 T} "*not available in a 2D*"]
checkTrue "Aggregator: missing material rejected" [fails {section Aggregator 2 99 Vy} "*99*"]
checkTrue "Aggregator: code of the base section repeated" [fails {section Aggregator 2 5 Mz -section 1} "*twice*"]
checkTrue "Aggregator: missing base section rejected" [fails {section Aggregator 2 5 Vy -section 42} "*42*"]
section Aggregator 2 5 Vy -section 1
node 1 0.0 0.0; node 2 0.0 0.0
checkTrue "zeroLengthSection: unknown section rejected" [fails {element zeroLengthSection 1 1 2 77} "*77*"]
checkTrue "zeroLengthSection: parallel orient vectors rejected" \
    [fails {element zeroLengthSection 1 1 2 2 -orient 1 0 0 2 0 0} "*parallel*"]
checkTrue "zeroLengthSection: orient out of the plane rejected in 2D" \
    [fails {element zeroLengthSection 1 1 2 2 -orient 1 0 0 0 0 1} "*plane*"]
checkTrue "no element was created by the failed commands" [expr {[llength [getEleTags]] == 0}]
element zeroLengthSection 1 1 2 2
fix 1 1 1 1
timeSeries Linear 1
set N 100.0; set V 5.0; set M 30.0
pattern Plain 1 1 { load 2 $N $V $M }
constraints Plain; numberer Plain; system BandGeneral
test NormDispIncr 1e-12 10; algorithm Newton; integrator LoadControl 1.0; analysis Static
checkTrue "zeroLengthSection over Aggregator(Elastic + Vy): analyze" [expr {[analyze 1] == 0}]
check "zeroLengthSection: axial = N/EA" [nodeDisp 2 1] [expr {$N / (2.0e8 * 0.02)}] 1e-12
check "zeroLengthSection: shear = V/k (Aggregator Vy spring)" [nodeDisp 2 2] [expr {$V / 1.0e5}] 1e-12
check "zeroLengthSection: rotation = M/EI" [nodeDisp 2 3] [expr {$M / (2.0e8 * 3.0e-4)}] 1e-12

# ------------------------------------------------------------------ 3D
wipe
model basic -ndm 3 -ndf 6
checkTrue "section Elastic 3D: missing J rejected" [fails {section Elastic 1 2.0e8 0.02 3e-4 2e-4 8e7} "*J*"]
checkTrue "section Elastic 3D: alphaY without alphaZ rejected" \
    [fails {section Elastic 1 2.0e8 0.02 3e-4 2e-4 8e7 5e-4 0.8} "*alphaZ*"]
# With shear factors the 3D section has all six resultants, so the zero-length section restrains
# every relative motion of its nodes.
section Elastic 1 2.0e8 0.02 3.0e-4 2.0e-4 8.0e7 5.0e-4 0.8 0.8
checkTrue "geomTransf Corotational 3D: missing vecxz rejected" [fails {geomTransf Corotational 1} "*vecxz*"]
geomTransf Corotational 1 0.0 0.0 1.0
node 1 0 0 0; node 2 4.0 0 0; node 3 4.0 0 0
checkTrue "geomTransf Corotational: vecxz parallel to the axis rejected" \
    [fails {geomTransf Corotational 2 1.0 0.0 0.0; element elasticBeamColumn 9 1 2 0.02 2e8 8e7 5e-4 2e-4 3e-4 2} "*parallel*"]
checkTrue "forceBeamColumn -cMass accepted" \
    [expr {![catch {element forceBeamColumn 1 1 2 3 1 1 -mass 2.0 -cMass}]}]
element zeroLengthSection 2 2 3 1 -orient 1 0 0 0 1 0
fix 1 1 1 1 1 1 1
timeSeries Linear 1
set T 10.0
pattern Plain 1 1 { load 3 0 0 0 $T 0 0 }
constraints Plain; numberer Plain; system BandGeneral
test NormDispIncr 1e-12 10; algorithm Newton; integrator LoadControl 1.0; analysis Static
checkTrue "3D model with Corotational forceBeamColumn + zeroLengthSection: analyze" [expr {[analyze 1] == 0}]
# twist = T L/GJ (member, Elastic section's GJ) + T/GJ (zero-length section, unit length)
set GJ [expr {8.0e7 * 5.0e-4}]
check "twist of member + zero-length section = T (L + 1)/GJ" [nodeDisp 3 4] [expr {$T * (4.0 + 1.0) / $GJ}] 1e-9
finish
