# SPDX-License-Identifier: MIT
# `analysis Transient -numSubLevels n -numSubSteps m`: a step that fails is retried as m smaller
# steps, and the result equals running the smaller steps directly.
#
# Source: the required behaviour (analysis ... -numSubLevels n -numSubSteps m: "on a
# failed step, retry it as m smaller steps, down to n levels"). Construction: a linear SDF system
# (m = 1, k = 100, wn = 10) under a step load P = 1 from rest, Newmark average acceleration, and a
# convergence test NormDispIncr with ONE iteration allowed and tol = 1.5e-3. For a linear system
# the first Newton iteration is exact and its increment is the whole step's displacement change:
# with dt = 0.1 from rest (zero initial acceleration, as in OpenSees) that is
# u1 = P / (k + 4 m / dt^2) = 2e-3 > tol, so the step fails; with dt/10 every increment is below
# |v|max dt/10 <= (P/(k wn)) wn * 0.01 = 1e-3 < tol, so the sub-steps pass.
source [file join [file dirname [info script]] .. lib check.tcl]

set TOL 1e-12

proc sdof {subOptions maxIter tol} {
  wipe
  model basic -ndm 1 -ndf 1
  node 1 0.0
  node 2 0.0 -mass 1.0
  fix 1 1
  uniaxialMaterial Elastic 1 100.0
  element zeroLength 1 1 2 -mat 1 -dir 1
  timeSeries Constant 1
  pattern Plain 1 1 { load 2 1.0 }
  constraints Plain; numberer Plain; system BandGeneral
  test NormDispIncr $tol $maxIter
  algorithm Newton
  integrator Newmark 0.5 0.25
  analysis Transient {*}$subOptions
}

# reference: ten steps of 0.01 (converged tightly)
sdof {} 10 1e-14
if {[analyze 10 0.01] != 0} { error "reference run failed" }
set uRef [nodeDisp 2 1]
set vRef [nodeVel 2 1]

# without sub-stepping, the 0.1 step fails and the model stays at t = 0
sdof {} 1 1.5e-3
set rc [analyze 1 0.1]
checkTrue "without -numSubSteps the 0.1 s step fails (code $rc < 0)" [expr {$rc < 0}]
checkAbs "failed step: time stays 0" [getTime %.17g] 0.0 0.0
checkAbs "failed step: displacement stays 0" [nodeDisp 2 1] 0.0 0.0

# with one level of 10 sub-steps the same step succeeds and equals the reference
sdof {-numSubLevels 1 -numSubSteps 10} 1 1.5e-3
set rc [analyze 1 0.1]
checkTrue "with -numSubLevels 1 -numSubSteps 10 the step succeeds (code $rc)" [expr {$rc == 0}]
check "sub-stepped: time = 0.1" [getTime %.17g] 0.1 $TOL
check "sub-stepped: u(0.1) equals 10 direct steps of 0.01" [nodeDisp 2 1] $uRef $TOL
check "sub-stepped: v(0.1) equals 10 direct steps of 0.01" [nodeVel 2 1] $vRef $TOL
# the next step uses the full dt again (and is sub-stepped again)
set rc [analyze 1 0.1]
checkTrue "second step also succeeds by sub-stepping (code $rc)" [expr {$rc == 0}]
check "sub-stepped: time = 0.2" [getTime %.17g] 0.2 $TOL
wipe
finish
