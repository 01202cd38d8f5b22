# SPDX-License-Identifier: MIT
# Tcl twin of frame.py (the same commands, in Tcl): an RC portal frame, gravity, eigen, 2 s of a
# sine ground acceleration. Prints the same rows. Units kN, m, s, t.
wipe
model basic -ndm 2 -ndf 3
set height 4.0; set span 6.0
node 1 0.0 0.0
node 2 $span 0.0
node 3 0.0 $height
node 4 $span $height
fix 1 1 1 1
fix 2 1 1 1
mass 3 20.0 20.0 0.0
mass 4 20.0 20.0 0.0
uniaxialMaterial Concrete01 1 -32000.0 -0.0022 -7000.0 -0.008
uniaxialMaterial Concrete01 2 -27000.0 -0.002 -5000.0 -0.0045
uniaxialMaterial Steel01 3 440000.0 2.0e8 0.015
set b 0.35; set h 0.45; set cover 0.04; set bar 0.00049
set y1 [expr {$h / 2.0}]; set z1 [expr {$b / 2.0}]
section Fiber 1 {
  patch rect 1 10 1 [expr {$cover - $y1}] [expr {$cover - $z1}] [expr {$y1 - $cover}] [expr {$z1 - $cover}]
  patch rect 2 10 1 [expr {-$y1}] [expr {-$z1}] $y1 [expr {$cover - $z1}]
  patch rect 2 10 1 [expr {-$y1}] [expr {$z1 - $cover}] $y1 $z1
  patch rect 2 2 1 [expr {-$y1}] [expr {$cover - $z1}] [expr {$cover - $y1}] [expr {$z1 - $cover}]
  patch rect 2 2 1 [expr {$y1 - $cover}] [expr {$cover - $z1}] $y1 [expr {$z1 - $cover}]
  layer straight 3 3 $bar [expr {$y1 - $cover}] [expr {$z1 - $cover}] [expr {$y1 - $cover}] [expr {$cover - $z1}]
  layer straight 3 2 $bar 0.0 [expr {$z1 - $cover}] 0.0 [expr {$cover - $z1}]
  layer straight 3 3 $bar [expr {$cover - $y1}] [expr {$z1 - $cover}] [expr {$cover - $y1}] [expr {$cover - $z1}]
}
geomTransf PDelta 1
geomTransf Linear 2
beamIntegration Lobatto 1 1 5
element forceBeamColumn 1 1 3 1 1
element forceBeamColumn 2 2 4 1 1
element elasticBeamColumn 3 3 4 0.3 3.0e7 0.0064 2

timeSeries Linear 1
pattern Plain 1 1 {
  load 3 0.0 -350.0 0.0
  load 4 0.0 -350.0 0.0
}
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 25
algorithm Newton
integrator LoadControl 0.1
analysis Static
puts "gravityStatus [analyze 10]"
puts "gravity [nodeDisp 3 1] [nodeDisp 3 2] [nodeDisp 4 2] [nodeDisp 3 3]"
loadConst -time 0.0
puts "eigen [join [eigen 2]]"

wipeAnalysis
rayleigh 0.25 0.0 0.003 0.0
timeSeries Trig 2 0.0 2.0 0.4 -factor 4.0
pattern UniformExcitation 2 1 -accel 2
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
for {set step 1} {$step <= 200} {incr step} {
  set status [analyze 1 0.01]
  if {$status != 0} { puts "failed $step $status"; break }
  if {$step % 20 == 0} {
    set force [eleResponse 1 force]
    puts "step $step [nodeDisp 3 1] [nodeDisp 4 1] [nodeVel 3 1] [lrange $force 0 2]"
  }
}
