# SPDX-License-Identifier: MIT
# Tcl twin of truss.py: a zero-length spring in series with a two-bar truss, a static load, then
# cycles of a yielding (Steel01) spring by displacement control. Units kN, m.
wipe
model basic -ndm 2 -ndf 2
node 1 0.0 0.0
node 2 4.0 0.0
node 3 2.0 1.5
node 4 2.0 1.5
fix 1 1 1
fix 2 1 1
uniaxialMaterial Elastic 1 2.0e8
uniaxialMaterial Steel01 2 80.0 5.0e4 0.05
uniaxialMaterial Elastic 3 1.0e9
element truss 1 1 3 0.0004 1
element truss 2 2 3 0.0004 1
element zeroLength 3 3 4 -mat 2 3 -dir 1 2
timeSeries Linear 1
pattern Plain 1 1 { load 4 0.0 -60.0 }
constraints Plain
numberer RCM
system BandSPD
test NormUnbalance 1.0e-9 10
algorithm Newton
integrator LoadControl 1.0
analysis Static
set status [analyze 1]
puts "static $status [nodeDisp 3 2] [nodeDisp 4 2] [eleResponse 1 axialForce] [eleResponse 2 axialForce]"
loadConst -time 0.0
wipeAnalysis
pattern Plain 2 1 { load 4 1.0 0.0 }
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-12 20
algorithm Newton
foreach target {0.006 -0.006 0.008} {
  set steps 8
  set increment [expr {($target - [nodeDisp 4 1]) / $steps}]
  integrator DisplacementControl 4 1 $increment
  analysis Static
  for {set i 0} {$i < $steps} {incr i} {
    set status [analyze 1]
    puts "cycle $status [nodeDisp 4 1] [nodeDisp 3 1] [getLoadFactor 2] [lindex [eleResponse 3 force] 0]"
  }
}
reactions
puts "reactions [nodeReaction 1 1] [nodeReaction 1 2] [nodeReaction 2 1] [nodeReaction 2 2]"
