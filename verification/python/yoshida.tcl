# SPDX-License-Identifier: MIT
# Tcl twin of yoshida.py: a yoshidaBearing under a vertical load driven around a growing
# figure-of-eight orbit by imposed displacements. Prints the same rows. Units kN, m.
set pi [expr {acos(-1.0)}]
set area 0.64; set rubber 0.16
lassign {0.435794 0.0683367 0.115167 0.831926 0.698464 0.0393774 0.000947439} y0 u0 n a0 b q g
wipe
model basic -ndm 3 -ndf 6
node 1 0.0 0.0 0.0
node 2 0.0 0.0 0.0
fix 1 1 1 1 1 1 1
fix 2 0 0 0 1 1 1
biaxialMaterial Yoshida 1 [expr {$y0 * 1000.0 * $area}] [expr {$u0 * $rubber}] $n $a0 $b $q $g
element yoshidaBearing 1 1 2 1 -Tr $rubber -Kv 2.0e6 -limits 2.5 3.0
set steps 240
set xs {0.0}; set ys {0.0}
for {set i 1} {$i <= $steps} {incr i} {
  lappend xs [expr {0.3 * $rubber * (1 + double($i) / $steps) * sin(2 * $pi * $i / 80)}]
  lappend ys [expr {0.2 * $rubber * (1 + double($i) / $steps) * sin(4 * $pi * $i / 80)}]
}
timeSeries Path 1 -dt 1.0 -values $xs
timeSeries Path 2 -dt 1.0 -values $ys
timeSeries Constant 3
pattern Plain 1 1 { sp 2 1 1.0 }
pattern Plain 2 2 { sp 2 2 1.0 }
pattern Plain 3 3 { load 2 0.0 0.0 -800.0 0.0 0.0 0.0 }
constraints Transformation
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-11 30
algorithm Newton
integrator LoadControl 1.0
analysis Static
for {set step 1} {$step <= $steps} {incr step} {
  set status [analyze 1]
  if {$status != 0} { puts "failed $step $status"; break }
  if {$step % 10 == 0} {
    set f [eleResponse 1 basicForce]
    puts "step $step [nodeDisp 2 1] [nodeDisp 2 2] [nodeDisp 2 3] [lrange $f 0 2] [eleResponse 1 shearStrain]"
  }
}
puts "energy [eleResponse 1 dissipatedEnergy] [eleResponse 1 maxShearStrain]"
