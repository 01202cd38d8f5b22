# SPDX-License-Identifier: MIT
# Tcl twin of supports.py: a two-span continuous beam under member loads and a support settlement,
# then a spring chain whose supports move by a MultipleSupport pattern. Prints the same rows.
# Units kN, m, s, t.
wipe
model basic -ndm 2 -ndf 3
for {set i 0} {$i < 5} {incr i} { node [expr {$i + 1}] [expr {3.0 * $i}] 0.0 }
fix 1 1 1 0
fix 5 0 1 0
section Elastic 1 3.0e7 0.12 1.6e-3
geomTransf Linear 1
beamIntegration Legendre 1 1 3
for {set e 1} {$e <= 4} {incr e} { element dispBeamColumn $e $e [expr {$e + 1}] 1 1 }
timeSeries Linear 1
pattern Plain 1 1 {
  eleLoad -ele 1 2 -type -beamUniform -12.0
  eleLoad -range 3 4 -type -beamPoint -30.0 0.4
  sp 3 2 -0.002
  load 5 5.0 0.0 0.0
}
constraints Transformation
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-12 10
algorithm Newton
integrator LoadControl 0.5
analysis Static
puts "beamStatus [analyze 2]"
puts "beamDisp [nodeDisp 2 2] [nodeDisp 3 2] [nodeDisp 4 2] [nodeDisp 5 1] [nodeDisp 1 3]"
puts "beamForces [eleResponse 2 localForce] [eleResponse 3 localForce]"
reactions
puts "beamReactions [nodeReaction 1 2] [nodeReaction 3 2] [nodeReaction 5 2]"

wipe
model basic -ndm 1 -ndf 1
node 1 0.0
node 2 0.0 -mass 2.0
node 3 0.0 -mass 1.0
node 4 0.0
fix 1 1
fix 4 1
uniaxialMaterial Elastic 1 300.0
uniaxialMaterial Elastic 2 150.0 2.0
element zeroLength 1 1 2 -mat 1 -dir 1
element zeroLength 2 2 3 -mat 2 -dir 1
element zeroLength 3 3 4 -mat 1 -dir 1
timeSeries Path 1 -dt 0.1 -values {0.0 0.004 0.010 0.013 0.011 0.006 0.002 0.0 -0.001 0.0}
timeSeries Path 2 -dt 0.1 -values {0.0 -0.002 -0.003 0.001 0.006 0.008 0.007 0.004 0.002 0.0}
pattern MultipleSupport 1 {
  groundMotion 1 Plain -disp 1
  groundMotion 2 Plain -disp 2
  imposedMotion 1 1 1
  imposedMotion 4 1 2
}
constraints Transformation
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 10
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
for {set step 1} {$step <= 60} {incr step} {
  set status [analyze 1 0.02]
  if {$status != 0} { puts "failed $step $status"; break }
  if {$step % 5 == 0} {
    puts "chain $step [nodeDisp 1 1] [nodeDisp 2 1] [nodeDisp 3 1] [nodeDisp 4 1] [nodeVel 2 1] [lindex [eleResponse 2 force] 1]"
  }
}
