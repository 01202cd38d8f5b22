# SPDX-License-Identifier: MIT
# Circular RC pier (D = 1.8 m, 9 m, kN-m) as one force-based element, 5 Lobatto points,
# Concrete02 core and cover and 36 Steel02 bars, P-Delta, 8 % axial load, pushed by displacement
# control to 0.21 m in 0.0015 m steps (OpenSees 3.8's element stops finding section forces near
# 0.22 m, in the softening branch). Our own model for timing dabs against OpenSees.
#
#   dabs|OpenSees pushover.tcl nSteps outDir
set nSteps [expr {$argc > 0 ? [lindex $argv 0] : 140}]
set outDir [expr {$argc > 1 ? [lindex $argv 1] : "pushover-out"}]
file mkdir $outDir
source [file join [file dirname [info script]] common.tcl]
wipe
model basic -ndm 3 -ndf 6
set PI [expr {acos(-1.0)}]
uniaxialMaterial Concrete02 1 -38000.0 -0.0024 -9000.0 -0.018 0.1 2800.0 1.4e6
uniaxialMaterial Concrete02 2 -30000.0 -0.002 -5000.0 -0.005 0.1 2500.0 1.2e6
uniaxialMaterial Steel02 3 420000.0 2.0e8 0.012 18.0 0.925 0.15
set D 1.8; set cover 0.06; set rCore [expr {$D/2.0 - $cover}]
section Fiber 1 -GJ [expr {1.0e7*$PI*pow($D,4)/32.0}] {
  patch circ 1 18 8 0.0 0.0 0.0 $rCore 0.0 360.0
  patch circ 2 18 2 0.0 0.0 $rCore [expr {$D/2.0}] 0.0 360.0
  layer circ 3 36 0.000804 0.0 0.0 [expr {$rCore - 0.02}] 0.0 350.0
}
beamIntegration Lobatto 1 1 5
geomTransf PDelta 1 1.0 0.0 0.0
node 1 0 0 0
node 2 0 0 9.0
fix 1 1 1 1 1 1 1
element forceBeamColumn 1 1 2 1 1
set P [expr {0.08*30000.0*$PI*$D*$D/4.0}]
timeSeries Constant 1
pattern Plain 1 1 { load 2 0 0 [expr {-$P}] 0 0 0 }
constraints Plain; numberer Plain; system BandGeneral
test NormDispIncr 1.0e-8 50; algorithm Newton
integrator LoadControl 0.1; analysis Static
analyze 10
loadConst -time 0.0
timeSeries Linear 2
pattern Plain 2 2 { load 2 1.0 0 0 0 0 0 }
recorder Node -file [file join $outDir tip.out] -time -precision 12 -node 2 -dof 1 disp
recorder Element -file [file join $outDir force.out] -time -precision 12 -ele 1 localForce
integrator DisplacementControl 2 1 0.0015
timedAnalyze "pushover steps=$nSteps" $nSteps
wipe
