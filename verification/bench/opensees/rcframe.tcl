# SPDX-License-Identifier: MIT
# Two-storey, two-bay reinforced-concrete frame in 2D (kN, m, s): force-based columns and
# displacement-based beams with fiber sections (Concrete01 confined core and cover, Steel02 bars),
# gravity by load control, then the El Centro NS record (Newmark, Newton, NormDispIncr 1e-8,
# BandGeneral, RCM). Our own model for timing dabs against OpenSees on one input.
#
#   dabs|OpenSees rcframe.tcl nSteps outDir
set nSteps [expr {$argc > 0 ? [lindex $argv 0] : 1500}]
set outDir [expr {$argc > 1 ? [lindex $argv 1] : "rcframe-out"}]
file mkdir $outDir
source [file join [file dirname [info script]] common.tcl]

wipe
model basic -ndm 2 -ndf 3
set g 9.81
set bay 6.0; set storey 3.5
foreach {tag x y} [list 1 0 0  2 $bay 0  3 [expr {2*$bay}] 0] {
  node $tag $x $y
  fix $tag 1 1 1
}
set m 40.0
foreach level {1 2} {
  foreach col {0 1 2} {
    node [expr {10*$level+$col+1}] [expr {$col*$bay}] [expr {$level*$storey}] -mass $m $m 0.0
  }
}
uniaxialMaterial Concrete01 1 -34000.0 -0.004 -24000.0 -0.014
uniaxialMaterial Concrete01 2 -27600.0 -0.002 0.0 -0.006
uniaxialMaterial Steel02 3 420000.0 2.0e8 0.01 18.0 0.925 0.15
proc rcSection {tag b h cover barArea nBars} {
  set y1 [expr {$h/2.0}]; set z1 [expr {$b/2.0}]
  section Fiber $tag {
    patch rect 1 12 1 [expr {$cover-$y1}] [expr {$cover-$z1}] [expr {$y1-$cover}] [expr {$z1-$cover}]
    patch rect 2 12 1 [expr {-$y1}] [expr {$z1-$cover}] $y1 $z1
    patch rect 2 12 1 [expr {-$y1}] [expr {-$z1}] $y1 [expr {$cover-$z1}]
    patch rect 2 2 1 [expr {-$y1}] [expr {$cover-$z1}] [expr {$cover-$y1}] [expr {$z1-$cover}]
    patch rect 2 2 1 [expr {$y1-$cover}] [expr {$cover-$z1}] $y1 [expr {$z1-$cover}]
    layer straight 3 $nBars $barArea [expr {$y1-$cover}] [expr {$z1-$cover}] [expr {$y1-$cover}] [expr {$cover-$z1}]
    layer straight 3 $nBars $barArea [expr {$cover-$y1}] [expr {$z1-$cover}] [expr {$cover-$y1}] [expr {$cover-$z1}]
  }
}
rcSection 1 0.5 0.5 0.05 0.000491 4
rcSection 2 0.4 0.6 0.05 0.000491 3
beamIntegration Lobatto 1 1 5
beamIntegration Legendre 2 2 3
geomTransf PDelta 1
geomTransf Linear 2
set e 1
foreach col {0 1 2} {
  element forceBeamColumn [incr e] [expr {$col+1}] [expr {11+$col}] 1 1
  element forceBeamColumn [incr e] [expr {11+$col}] [expr {21+$col}] 1 1
}
foreach level {1 2} {
  foreach col {0 1} {
    element dispBeamColumn [incr e] [expr {10*$level+$col+1}] [expr {10*$level+$col+2}] 2 2
  }
}
timeSeries Linear 1
pattern Plain 1 1 {
  foreach level {1 2} { foreach col {0 1 2} { load [expr {10*$level+$col+1}] 0.0 [expr {-$m*$g}] 0.0 } }
}
constraints Plain; numberer RCM; system BandGeneral
test NormDispIncr 1.0e-8 20; algorithm Newton
integrator LoadControl 0.1; analysis Static
if {[analyze 10] != 0} { error "gravity analysis failed" }
loadConst -time 0.0
wipeAnalysis

set plain [file join $outDir elcentro.txt]
set recDt [writePlainRecord [findRecord elCentro.at2] $plain]
timeSeries Path 2 -dt $recDt -filePath $plain -factor [expr {1.5*$g}]
pattern UniformExcitation 2 1 -accel 2
rayleigh 0.3 0.0 0.002 0.0
recorder Node -file [file join $outDir disp.out] -time -precision 12 -node 11 21 -dof 1 disp
recorder Element -file [file join $outDir force.out] -time -precision 12 -ele 2 4 6 localForce

constraints Plain; numberer RCM; system BandGeneral
test NormDispIncr 1.0e-8 20; algorithm Newton
integrator Newmark 0.5 0.25; analysis Transient
timedAnalyze "rcframe steps=$nSteps" $nSteps 0.01
wipe
