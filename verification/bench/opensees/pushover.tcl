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
circularPier {
  D 1.8 cover 0.06 height 9.0
  core {-38000.0 -0.0024 -9000.0 -0.018 0.1 2800.0 1.4e6}
  coverConcrete {-30000.0 -0.002 -5000.0 -0.005 0.1 2500.0 1.2e6}
  steel {420000.0 2.0e8 0.012 18.0 0.925 0.15}
  G 1.0e7 sectors 18 bars 36 barArea 0.000804 lastBarAngle 350.0
  axialRatio 0.08 gravitySteps 10
}
timeSeries Linear 2
pattern Plain 2 2 { load 2 1.0 0 0 0 0 0 }
recorder Node -file [file join $outDir tip.out] -time -precision 12 -node 2 -dof 1 disp
recorder Element -file [file join $outDir force.out] -time -precision 12 -ele 1 localForce
integrator DisplacementControl 2 1 0.0015
timedAnalyze "pushover steps=$nSteps" $nSteps
wipe
