# SPDX-License-Identifier: MIT
# A small ensemble for the job farm's tests and benchmark: yielding single-degree-of-freedom
# oscillators (Steel01 spring, mass, Rayleigh damping) under a sine ground acceleration, with run
# lengths that differ by 10x from job to job, one job whose analysis fails and one whose command
# raises an error.
#
#   dabs jobs.tcl outDir ?count? ?logFile? ?lengthFactor? ?faults?
#   mpirun -n 2 dabs-mp jobs.tcl outDir ...
#
#   count         number of jobs (default 16)
#   logFile       each job appends "<id> <process number> <operating-system pid>" to it when it
#                 starts (the tests read which jobs a run did); "" for none
#   lengthFactor  scales every job's number of steps (default 1)
#   faults        1 (default): job 5's analysis fails and job 9 raises an error; 0: all 16 run
# Prints the ensemble's summary and the wall time.

set outDir [lindex $argv 0]
set count [expr {$argc > 1 ? [lindex $argv 1] : 16}]
set logFile [expr {$argc > 2 ? [lindex $argv 2] : ""}]
set lengthFactor [expr {$argc > 3 ? [lindex $argv 3] : 1.0}]
set faults [expr {$argc > 4 ? [lindex $argv 4] : 1}]
set progress [expr {$argc > 5 ? [lindex $argv 5] : 0}]

# One job: the oscillator with yield force fy under amplitude ag (m/s^2) for `steps` steps of
# 0.005 s. kind: ok | diverge (a convergence test no step can pass: the analysis fails and its code
# is returned) | error (a Tcl error before the analysis).
proc oscillator {job} {
  dict with job {}
  if {$::logFile ne ""} {
    set fh [open $::logFile a]
    puts $fh "$id [getPID] [pid]"
    close $fh
  }
  if {$kind eq "error"} { error "job $id: no such material \"$fy\"" }
  model basic -ndm 1 -ndf 1
  node 1 0.0
  node 2 0.0 -mass 1.0
  fix 1 1
  uniaxialMaterial Steel01 1 $fy 400.0 0.05
  element zeroLength 1 1 2 -mat 1 -dir 1
  timeSeries Trig 1 0.0 1000.0 0.6 -factor $ag
  pattern UniformExcitation 1 1 -accel 1
  rayleigh 0.0 0.0 0.0 0.0025
  constraints Plain
  numberer Plain
  system BandGeneral
  if {$kind eq "diverge"} { test NormDispIncr 1.0e-30 2 } else { test NormDispIncr 1.0e-12 25 }
  algorithm Newton
  integrator Newmark 0.5 0.25
  analysis Transient
  set peak 0.0
  set code 0
  for {set i 0} {$i < $steps} {incr i} {
    set code [analyze 1 0.005]
    if {$code != 0} { break }
    set u [nodeDisp 2 1]
    if {abs($u) > abs($peak)} { set peak $u }
  }
  return [list code $code peak $peak residual [nodeDisp 2 1] time [getTime %.17g]]
}

# Job i: steps from 100 to 1000 (a 10x spread, in an order that mixes long and short jobs).
set jobs {}
for {set i 1} {$i <= $count} {incr i} {
  set kind ok
  if {$faults && $i == 5} { set kind diverge }
  if {$faults && $i == 9} { set kind error }
  set steps [expr {int(round($lengthFactor * 100 * (1 + (7 * $i) % 10)))}]
  lappend jobs [list id [format "osc%02d" $i] kind $kind fy [expr {10.0 + $i}] ag [expr {3.0 + 0.5 * $i}] steps $steps]
}
set t0 [clock milliseconds]
set summary [ensemble run $jobs oscillator -out $outDir {*}[expr {$progress ? "-progress" : ""}]]
if {[getPID] == 0} {
  puts "summary $summary"
  puts [format "wall %.3f s on %d process(es)" [expr {([clock milliseconds] - $t0) / 1000.0}] [getNP]]
}
