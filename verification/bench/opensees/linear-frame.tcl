# SPDX-License-Identifier: MIT
# Linear 3D frame (kN, m, s): a 6 x 6 bay, 10-storey building of elastic beams and columns with
# rigid-slab masses at the floor nodes, 5 % Rayleigh damping, the El Centro NS record along X and
# 0.5 of it along Y, Newmark average acceleration with `algorithm Linear` (one factorisation for
# the whole run). Our own model for timing dabs against OpenSees.
#
#   dabs|OpenSees linear-frame.tcl nSteps outDir ?-factorOnce?
set nSteps [expr {$argc > 0 ? [lindex $argv 0] : 1500}]
set outDir [expr {$argc > 1 ? [lindex $argv 1] : "linear-frame-out"}]
file mkdir $outDir
source [file join [file dirname [info script]] common.tcl]
wipe
model basic -ndm 3 -ndf 6
set g 9.81; set nb 6; set ns 10; set bay 6.0; set h 3.2
proc nid {i j k} { return [expr {10000*$k + 100*$i + $j + 1}] }
for {set k 0} {$k <= $ns} {incr k} {
  for {set i 0} {$i <= $nb} {incr i} {
    for {set j 0} {$j <= $nb} {incr j} {
      if {$k == 0} {
        node [nid $i $j $k] [expr {$i*$bay}] [expr {$j*$bay}] 0.0
        fix [nid $i $j $k] 1 1 1 1 1 1
      } else {
        node [nid $i $j $k] [expr {$i*$bay}] [expr {$j*$bay}] [expr {$k*$h}] -mass 30.0 30.0 0.0 0.0 0.0 0.0
      }
    }
  }
}
geomTransf Linear 1 1.0 0.0 0.0   ;# columns
geomTransf Linear 2 0.0 0.0 1.0   ;# beams
set E 3.0e7; set G 1.25e7
set e 0
for {set k 1} {$k <= $ns} {incr k} {
  for {set i 0} {$i <= $nb} {incr i} {
    for {set j 0} {$j <= $nb} {incr j} {
      element elasticBeamColumn [incr e] [nid $i $j [expr {$k-1}]] [nid $i $j $k] 0.36 $E $G 0.018 0.0108 0.0108 1
      if {$i < $nb} { element elasticBeamColumn [incr e] [nid $i $j $k] [nid [expr {$i+1}] $j $k] 0.24 $E $G 0.005 0.0032 0.0072 2 }
      if {$j < $nb} { element elasticBeamColumn [incr e] [nid $i $j $k] [nid $i [expr {$j+1}] $k] 0.24 $E $G 0.005 0.0032 0.0072 2 }
    }
  }
}
set plain [file join $outDir elcentro.txt]
set recDt [writePlainRecord [findRecord elCentro.at2] $plain]
timeSeries Path 1 -dt $recDt -filePath $plain -factor $g
timeSeries Path 2 -dt $recDt -filePath $plain -factor [expr {0.5*$g}]
pattern UniformExcitation 1 1 -accel 1
pattern UniformExcitation 2 2 -accel 2
rayleigh 0.35 0.0 0.004 0.0
recorder Node -file [file join $outDir roof.out] -time -precision 12 -node [nid 0 0 $ns] [nid $nb $nb $ns] -dof 1 2 disp
recorder Element -file [file join $outDir base.out] -time -precision 12 -ele 1 localForce
constraints Plain; numberer RCM; system BandSPD
set algorithmArgs [expr {$argc > 2 ? [lindex $argv 2] : ""}]
test NormDispIncr 1.0e-8 10; algorithm Linear {*}$algorithmArgs
integrator Newmark 0.5 0.25; analysis Transient
timedAnalyze "linear-frame steps=$nSteps" $nSteps 0.01
wipe
