# SPDX-License-Identifier: MIT
# A small 3D steel frame under a built-in ground motion: the program's main job until the bridge
# case study exists. Units: kN, m, s. Runs anywhere: the motion is a sine pulse, no data files.
#
#   dabs verification/examples/frame3d.tcl ?bays? ?stories?

set baysX   [expr {$argc > 0 ? [lindex $argv 0] : 3}]
set baysY   [expr {$argc > 1 ? [lindex $argv 1] : 2}]
set stories [expr {$argc > 2 ? [lindex $argv 2] : 4}]
set span 6.0          ;# m
set height 3.5        ;# m
set E 2.0e8           ;# kN/m2 (steel)
set G 7.7e7
set A 0.05            ;# m2 columns and beams
set Iz 1.2e-3          ;# m4
set Iy 8.0e-4
set J 1.0e-4
set floorMass 60.0    ;# t per node (kN s2/m)
set g 9.81

wipe
model basic -ndm 3 -ndf 6
proc nodeTag {i j k} { return [expr {1000*$k + 100*$i + $j + 1}] }
for {set k 0} {$k <= $stories} {incr k} {
  for {set i 0} {$i <= $baysX} {incr i} {
    for {set j 0} {$j <= $baysY} {incr j} {
      set tag [nodeTag $i $j $k]
      node $tag [expr {$i*$span}] [expr {$j*$span}] [expr {$k*$height}]
      if {$k == 0} { fix $tag 1 1 1 1 1 1 } else { mass $tag $floorMass $floorMass 0.0 0.0 0.0 0.0 }
    }
  }
}
geomTransf Linear 1 1 0 0     ;# columns (local x vertical)
geomTransf Linear 2 0 0 1     ;# beams
set ele 0
for {set k 1} {$k <= $stories} {incr k} {
  for {set i 0} {$i <= $baysX} {incr i} {
    for {set j 0} {$j <= $baysY} {incr j} {
      element elasticBeamColumn [incr ele] [nodeTag $i $j [expr {$k-1}]] [nodeTag $i $j $k] $A $E $G $J $Iy $Iz 1
      if {$i < $baysX} { element elasticBeamColumn [incr ele] [nodeTag $i $j $k] [nodeTag [expr {$i+1}] $j $k] $A $E $G $J $Iy $Iz 2 }
      if {$j < $baysY} { element elasticBeamColumn [incr ele] [nodeTag $i $j $k] [nodeTag $i [expr {$j+1}] $k] $A $E $G $J $Iy $Iz 2 }
    }
  }
}

# Periods, then 5% Rayleigh damping on modes 1 and 3.
set lambda [eigen 3]
set w1 [expr {sqrt([lindex $lambda 0])}]
set w3 [expr {sqrt([lindex $lambda 2])}]
set zeta 0.05
rayleigh [expr {2*$zeta*$w1*$w3/($w1+$w3)}] 0.0 [expr {2*$zeta/($w1+$w3)}] 0.0

# Built-in motion: three cycles of a 0.35 g sine at the first period, at 30 degrees to x.
set T1 [expr {2*acos(-1)/$w1}]
set angle [expr {30.0*acos(-1)/180}]
timeSeries Trig 1 0.0 [expr {3*$T1}] $T1 -factor [expr {0.35*$g*cos($angle)}]
timeSeries Trig 2 0.0 [expr {3*$T1}] $T1 -factor [expr {0.35*$g*sin($angle)}]
pattern UniformExcitation 1 1 -accel 1
pattern UniformExcitation 2 2 -accel 2

set roof [nodeTag $baysX $baysY $stories]
recorder Node -file frame3d-roof.out -time -node $roof -dof 1 2 disp
constraints Transformation
numberer RCM
system SparseSYM
test NormDispIncr 1e-8 10
algorithm Linear
integrator Newmark 0.5 0.25
analysis Transient
set dt 0.005
set steps [expr {int(6*$T1/$dt)}]
set t0 [clock microseconds]
set status [analyze $steps $dt]
set seconds [expr {([clock microseconds]-$t0)*1e-6}]
set peak 0.0
set f [open frame3d-roof.out]
while {[gets $f line] >= 0} {
  set ux [lindex $line 1]; set uy [lindex $line 2]
  set peak [expr {max($peak, sqrt($ux*$ux + $uy*$uy))}]
}
close $f
puts [format "3D frame: %d nodes, %d elements, periods %.3f %.3f %.3f s" \
  [llength [getNodeTags]] [llength [getEleTags]] $T1 [expr {2*acos(-1)/sqrt([lindex $lambda 1])}] [expr {2*acos(-1)/$w3}]]
puts [format "%d Newmark steps of %.3f s: status %d, %.2f s wall time; peak roof displacement %.4f m" \
  $steps $dt $status $seconds $peak]
exit [expr {$status == 0 ? 0 : 1}]
