# SPDX-License-Identifier: MIT
# Tcl twin of contact.py: a block pushed obliquely onto a fixed face (nodeToSurface with
# restitution and friction). Prints the same rows. Units kN, m, s, t.
wipe
model basic -ndm 3 -ndf 3
node 1 0.0 -1.0 -1.0
node 2 0.0 -1.0 1.0
node 3 0.0 1.0 1.0
node 4 0.0 1.0 -1.0
node 5 -0.02 0.0 0.0 -mass 2.0 2.0 2.0
foreach n {1 2 3 4} { fix $n 1 1 1 }
fix 5 0 0 1
element nodeToSurface 1 5 1 2 3 4 -K 4.0e5 -e 0.7 -mu_s 0.3 -mu_k 0.25 -Kt 2.0e5 -masses 2.0 1.0e6
timeSeries Rectangular 1 0.0 0.15
pattern Plain 1 1 { load 5 30.0 12.0 0.0 }
constraints Plain
numberer Plain
system FullGeneral
test NormDispIncr 1.0e-12 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
for {set step 1} {$step <= 300} {incr step} {
  set status [analyze 1 0.001]
  if {$status != 0} { puts "failed $step $status"; break }
  if {$step % 15 == 0} {
    puts "step $step [nodeDisp 5 1] [nodeDisp 5 2] [nodeVel 5 1] [eleResponse 1 gap] [eleResponse 1 contactForce] [eleResponse 1 status]"
  }
}
puts "energy [eleResponse 1 dissipatedEnergy] [eleResponse 1 impulse]"
