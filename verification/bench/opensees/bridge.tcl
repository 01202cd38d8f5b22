# SPDX-License-Identifier: MIT
# Multi-span base-isolated bridge in the common OpenSees vocabulary, for timing dabs against
# OpenSees on the same input (verification/bench/opensees/compare.sh runs both).
#
#   dabs|OpenSees bridge.tcl nSpans nSteps outDir
#
# kN, m, s. nSpans simply supported 40 m spans (elastic girders, 4 elements a span, lumped mass)
# on zeroLength bearings (bilinear lead-rubber shear springs, stiff vertical) over nSpans+1
# circular RC piers (one forceBeamColumn each, 5 Lobatto points, 200 fibers: Concrete02 core and
# cover, Steel02 bars) of 8, 10 and 12 m in turn. Adjacent girder ends meet over
# each pier across a 50 mm expansion joint: a compression-only gap spring (ElasticPPGap) in the
# longitudinal direction. Gravity by load control, then the Takatori EW record at 30 degrees to the
# bridge axis (Newmark average acceleration, Newton, NormDispIncr 1e-8, UmfPack, RCM, dt 0.005 s).
# Records girder displacements, pier-top displacements and pier base forces.
set nSpans [expr {$argc > 0 ? [lindex $argv 0] : 3}]
set nSteps [expr {$argc > 1 ? [lindex $argv 1] : 4000}]
set outDir [expr {$argc > 2 ? [lindex $argv 2] : "bridge-bench-out"}]
file mkdir $outDir
source [file join [file dirname [info script]] common.tcl]

wipe
model basic -ndm 3 -ndf 6
set PI [expr {acos(-1.0)}]
set g 9.81
set L 40.0                 ;# span
set nEle 4                 ;# girder elements a span
set heights {8.0 10.0 12.0}

# Pier section: D = 2 m circular, 75 mm cover, 40 bars of 32 mm.
uniaxialMaterial Concrete02 1 -40000.0 -0.0025 -8000.0 -0.02 0.1 3000.0 1.5e6
uniaxialMaterial Concrete02 2 -30000.0 -0.002 -5000.0 -0.005 0.1 2500.0 1.2e6
uniaxialMaterial Steel02 3 400000.0 2.0e8 0.01 18.0 0.925 0.15
set D 2.0; set cover 0.075; set rCore [expr {$D/2.0 - $cover}]
set Jp [expr {$PI*pow($D,4)/32.0}]
section Fiber 1 -GJ [expr {1.04e7*$Jp}] {
  patch circ 1 16 8 0.0 0.0 0.0 $rCore 0.0 360.0
  patch circ 2 16 2 0.0 0.0 $rCore [expr {$D/2.0}] 0.0 360.0
  layer circ 3 40 0.000804 0.0 0.0 [expr {$rCore - 0.02}] 0.0 351.0
}
beamIntegration Lobatto 1 1 5
geomTransf PDelta 1 1.0 0.0 0.0     ;# piers (vertical)
geomTransf Linear 2 0.0 0.0 1.0     ;# girders (along X)

# Bearings: lead-rubber shear (Steel01: Fy, K1, b), stiff vertical, soft rocking, stiff torsion.
uniaxialMaterial Steel01 10 120.0 12000.0 0.12
uniaxialMaterial Elastic 11 4.0e6
uniaxialMaterial Elastic 12 2.0e5
uniaxialMaterial Elastic 13 1.0e3
# Expansion joint: compression-only, closes after 50 mm.
uniaxialMaterial ElasticPPGap 20 2.0e6 -1.0e8 -0.05

# Girder: A = 6 m^2, E = 3e7, Iy 3, Iz 40, J 6; mass 18 t/m lumped on its nodes.
set mGirder [expr {18.0*$L/$nEle}]
proc supportX {k} { return [expr {$k*$::L}] }

# Supports k = 0..nSpans, each a pier (a segment of a viaduct: the end piers would carry the
# next segments' spans too). Support k has ground node 100000+k, top (cap) node 200000+k. Span s
# (1..nSpans) has girder nodes 10*s + 0..nEle.
for {set k 0} {$k <= $nSpans} {incr k} {
  set x [supportX $k]
  set h [lindex $heights [expr {$k % [llength $heights]}]]
  node [expr {100000+$k}] $x 0.0 [expr {-$h}]
  node [expr {200000+$k}] $x 0.0 0.0 -mass 150.0 150.0 150.0 0.0 0.0 0.0
  fix [expr {100000+$k}] 1 1 1 1 1 1
  element forceBeamColumn [expr {100000+$k}] [expr {100000+$k}] [expr {200000+$k}] 1 1
  set cap($k) [expr {200000+$k}]
}
for {set s 1} {$s <= $nSpans} {incr s} {
  set x0 [supportX [expr {$s-1}]]
  for {set i 0} {$i <= $nEle} {incr i} {
    set m [expr {($i == 0 || $i == $nEle) ? 0.5*$mGirder : $mGirder}]
    node [expr {10*$s+$i}] [expr {$x0 + $i*$L/$nEle}] 0.0 0.0 -mass $m $m $m 0.0 0.0 0.0
  }
  for {set i 0} {$i < $nEle} {incr i} {
    element elasticBeamColumn [expr {10*$s+$i}] [expr {10*$s+$i}] [expr {10*$s+$i+1}] \
        6.0 3.0e7 1.25e7 6.0 3.0 40.0 2
  }
  # bearings under both ends of the span
  foreach {end k} [list 0 [expr {$s-1}] $nEle $s] {
    element zeroLength [expr {2000000+10*$s+($end>0)}] $cap($k) [expr {10*$s+$end}] \
        -mat 10 10 11 12 13 13 -dir 1 2 3 4 5 6
  }
}
# expansion joints over the piers: span s end meets span s+1 start
for {set s 1} {$s < $nSpans} {incr s} {
  element zeroLength [expr {3000000+$s}] [expr {10*$s+$nEle}] [expr {10*($s+1)}] -mat 20 -dir 1
}

# Gravity: girder and cap weights as nodal loads.
timeSeries Linear 1
pattern Plain 1 1 {
  for {set s 1} {$s <= $nSpans} {incr s} {
    for {set i 0} {$i <= $nEle} {incr i} {
      set m [expr {($i == 0 || $i == $nEle) ? 0.5*$mGirder : $mGirder}]
      load [expr {10*$s+$i}] 0.0 0.0 [expr {-$m*$g}] 0.0 0.0 0.0
    }
  }
  for {set k 0} {$k <= $nSpans} {incr k} { load [expr {200000+$k}] 0.0 0.0 [expr {-150.0*$g}] 0.0 0.0 0.0 }
}
constraints Plain
numberer RCM
system UmfPack
test NormDispIncr 1.0e-8 20
algorithm Newton
integrator LoadControl 0.1
analysis Static
if {[analyze 10] != 0} { error "gravity analysis failed" }
loadConst -time 0.0
wipeAnalysis

# Takatori EW at 30 degrees to the bridge axis.
set plain [file join $outDir takatori.txt]
set recDt [writePlainRecord [findRecord RSN1120_KOBE_TAK090.AT2] $plain]
timeSeries Path 2 -dt $recDt -filePath $plain -factor [expr {$g*cos($PI/6.0)}]
timeSeries Path 3 -dt $recDt -filePath $plain -factor [expr {$g*sin($PI/6.0)}]
pattern UniformExcitation 2 1 -accel 2
pattern UniformExcitation 3 2 -accel 3
# 3 % Rayleigh damping at 1 and 3 Hz, initial stiffness.
set w1 [expr {2.0*$PI*1.0}]; set w2 [expr {2.0*$PI*3.0}]; set z 0.03
rayleigh [expr {2.0*$z*$w1*$w2/($w1+$w2)}] 0.0 [expr {2.0*$z/($w1+$w2)}] 0.0

set mid [expr {$nEle/2}]
set girderNodes {}
for {set s 1} {$s <= $nSpans} {incr s} { lappend girderNodes [expr {10*$s+$mid}] [expr {10*$s+$nEle}] }
set pierTops {}; set piers {}
for {set k 0} {$k <= $nSpans} {incr k} { lappend pierTops [expr {200000+$k}]; lappend piers [expr {100000+$k}] }
recorder Node -file [file join $outDir girder-disp.out] -time -precision 17 -node {*}$girderNodes -dof 1 2 disp
recorder Node -file [file join $outDir pier-disp.out] -time -precision 17 -node {*}$pierTops -dof 1 2 disp
recorder Element -file [file join $outDir pier-force.out] -time -precision 17 -ele {*}$piers localForce

constraints Plain
numberer RCM
system UmfPack
test NormDispIncr 1.0e-8 20
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
timedAnalyze "bridge nSpans=$nSpans steps=$nSteps" $nSteps 0.005
