# SPDX-License-Identifier: MIT
# Pounding of two SDOF oscillators under the Takatori EW record (a benchmark): wall time
# against the error in the exit relative velocity of the first impact and in the peak contact
# force, for several steps, the error measured against a run with a 20x smaller step than the
# finest. Not a pass/fail test: prints CSV. Units kN, m, t, s.
#
#   dabs verification/pounding/bench/sdof_takatori.tcl ?duration?
source [file join [file dirname [info script]] .. .. lib check.tcl]
set duration [expr {$argc > 0 ? [lindex $argv 0] : 10.0}]
set g 9.81
set pi [expr {acos(-1.0)}]

proc readAT2 {path} {
  set f [open $path]; set lines [split [read $f] "\n"]; close $f
  return [concat {*}[lrange $lines 4 end]]
}
set accel [readAT2 [recordPath RSN1120_KOBE_TAK090.AT2]]

# SDOF 1: contactor node 1 (T1 = 1.0 s); SDOF 2: face 11-14 (T2 = 0.5 s), gap 0.05 m.
set m 500.0
set T1 1.0
set T2 0.5
set gap 0.05
proc run {dt} {
  global m T1 T2 gap accel g pi duration
  wipe
  model basic -ndm 3 -ndf 3
  node 1 0 0 0; node 101 0 0 0
  fix 101 1 1 1; fix 1 0 1 1
  mass 1 $m $m $m
  set i 10
  foreach {y z} {-1 -1  -1 1  1 1  1 -1} {
    incr i
    node $i $gap $y $z; node [expr {$i + 100}] $gap $y $z
    fix [expr {$i + 100}] 1 1 1; fix $i 0 1 1
    mass $i [expr {$m/4}] [expr {$m/4}] [expr {$m/4}]
  }
  uniaxialMaterial Elastic 1 [expr {4*$pi*$pi*$m/($T1*$T1)}]
  uniaxialMaterial Elastic 2 [expr {4*$pi*$pi*$m/4/($T2*$T2)}]
  element zeroLength 1 101 1 -mat 1 -dir 1
  foreach i {11 12 13 14} { element zeroLength $i [expr {$i + 100}] $i -mat 2 -dir 1 }
  # face 11 12 13 14: (b-a) x (d-a) = (0,0,2) x (0,2,0) = (-4,0,0): n = -x, towards node 1
  element nodeToSurface 50 1 11 12 13 14 -K 2.0e6 -e 0.65 -masses $m $m
  timeSeries Path 1 -dt 0.01 -values $accel -factor $g
  pattern UniformExcitation 1 1 -accel 1
  constraints Plain; numberer Plain; system UmfPack
  test NormDispIncr 1e-10 30; algorithm Newton
  integrator Newmark 0.5 0.25; analysis Transient -numSubLevels 3 -numSubSteps 4
  set peak 0.0; set exit ""; set was 0; set failed 0
  set t0 [clock microseconds]
  set n [expr {int(round($duration/$dt))}]
  for {set k 0} {$k < $n} {incr k} {
    if {[analyze 1 $dt] != 0} { incr failed; break }
    set st [eleResponse 50 status]
    set peak [expr {max($peak, [lindex [eleResponse 50 contactForce] 0])}]
    if {$exit eq "" && $was != 0 && $st == 0} { set exit [expr {[nodeVel 11 1] - [nodeVel 1 1]}] }
    set was $st
  }
  set t1 [clock microseconds]
  return [list [expr {($t1-$t0)*1e-6}] $peak $exit $failed]
}

set steps {0.01 0.005 0.0025 0.00125}
set ref [run [expr {[lindex $steps end]/20.0}]]
puts "dt,seconds,peak_force_kN,peak_force_rel_err,exit_velocity,exit_velocity_rel_err,failed_steps"
puts [format "%g,%.3f,%.6g,0,%.6g,0,%d (reference)" [expr {[lindex $steps end]/20.0}] {*}$ref]
foreach dt $steps {
  lassign [run $dt] sec peak exit failed
  puts [format "%g,%.3f,%.6g,%.2e,%.6g,%.2e,%d" $dt $sec $peak [expr {abs($peak/[lindex $ref 1] - 1)}] \
      $exit [expr {abs($exit/[lindex $ref 2] - 1)}] $failed]
}
