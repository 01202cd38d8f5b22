# SPDX-License-Identifier: MIT
# OpenSeesMP's parametric pattern, as its users write it: every process runs the whole script, and
# process getPID takes every getNP-th case of the study; the others send their results to process
# 0 (send -pid 0 / recv -pid ANY), and a barrier ends the study. Serially (getNP 1) process 0 runs
# every case. The cases: an elastic cantilever under a tip load P, whose tip deflection is
# P L^3 / (3 E I) (Euler-Bernoulli; the cubic elastic beam elements are exact for it).
#
#   dabs parametric.tcl      or      mpirun -n 2 dabs-mp parametric.tcl
source [file join [file dirname [info script]] .. lib check.tcl]

set pid [getPID]
set np [getNP]
set L 3.0; set E 2.0e8; set A 0.01; set I 1.0e-4
set TOL 1e-9

proc tipDeflection {P} {
  global L E A I
  wipe
  model basic -ndm 2 -ndf 3
  for {set i 0} {$i <= 4} {incr i} { node [expr {$i + 1}] [expr {$L * $i / 4.0}] 0.0 }
  fix 1 1 1 1
  geomTransf Linear 1
  for {set i 1} {$i <= 4} {incr i} { element elasticBeamColumn $i $i [expr {$i + 1}] $A $E $I 1 }
  timeSeries Linear 1
  pattern Plain 1 1 { load 5 0.0 [expr {-$P}] 0.0 }
  constraints Plain; numberer Plain; system BandGeneral
  test NormDispIncr 1e-12 10; algorithm Linear; integrator LoadControl 1.0; analysis Static
  if {[analyze 1] != 0} { error "analysis failed for P = $P" }
  return [nodeDisp 5 2]
}

set loads {10.0 20.0 35.0 50.0 80.0 125.0 200.0}
set mine {}
set count 0
foreach P $loads {
  if {$count % $np == $pid} { lappend mine $P [tipDeflection $P] }
  incr count
}
if {$pid == 0} {
  array set results $mine
  for {set p 1} {$p < $np} {incr p} {
    set from [recv -pid ANY message]
    array set results $message
    checkTrue "process 0 received the results of process $from" [expr {$from > 0 && $from < $np}]
  }
} else {
  send -pid 0 $mine
}
barrier

if {$pid == 0} {
  checkTrue "every case computed once ([array size results] of [llength $loads])" \
      [expr {[array size results] == [llength $loads]}]
  foreach P $loads {
    check "tip deflection P = $P, PL^3/3EI" [expr {-$results($P)}] [expr {$P * $L ** 3 / (3.0 * $E * $I)}] $TOL
  }
}
# Each process took its share: ceil or floor of cases / processes.
set share [expr {[llength $mine] / 2}]
checkTrue "process $pid ran its share ($share of [llength $loads] cases on $np processes)" \
    [expr {$share == ([llength $loads] - $pid + $np - 1) / $np}]
finish
