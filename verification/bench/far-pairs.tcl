# SPDX-License-Identifier: MIT
# Cost of contact pairs that are far apart: a row of J joints, each two 2 x 1 m girder-end faces
# of 4 nodes on elastic springs 0.2 m apart, shaken along the row (a sine of 0.5 s period); the
# same model is run without contact, with `pounding` pairs (8 per joint) given a search distance
# of 0.05 m (so they are far: they sleep), and with the pairs but no search distance (every pair
# evaluated at every iteration, none touching). Times are the CPU time (user + system, from
# /proc/self/stat, 10 ms ticks) of `analyze`, the smallest (and the median) of `repeat` runs, so
# other processes on the machine matter less; the counts (iterations, element updates, pattern
# changes) are exact.
#
#   dabs verification/bench/far-pairs.tcl ?joints? ?steps? ?repeat? ?csv? ?modes? ?order? ?process?
#
# `modes` (default "none far evaluated") runs a subset (e.g. one mode for valgrind); the
# comparison lines need "none" among them. Mode `removed` defines the far pairs and removes them
# (`remove element`) before the analysis: the analysis of the model without pairs, on the heap
# that defining the pairs between the joints' nodes and springs left (a control: what the
# model's memory layout costs, apart from anything the pairs do). `order`: "joint" (default) defines each joint's pairs
# with its nodes and springs, as a viaduct script built span by span does; "after" defines all
# pairs after the rest of the model. `process`: "fresh" (default) runs each model in a process of
# its own, the modes in turn within each repeat; "same" runs them all in this process, one mode's
# repeats after the other's. A model built after other models were wiped runs slower (its data
# land in the holes they left), whatever its mode, so in one process the later modes pay for the
# earlier ones.
set J      [expr {$argc > 0 ? [lindex $argv 0] : 100}]
set steps  [expr {$argc > 1 ? [lindex $argv 1] : 1000}]
set repeat [expr {$argc > 2 ? [lindex $argv 2] : 3}]
set csv    [expr {$argc > 3 ? [lindex $argv 3] : ""}]
set modes  [expr {$argc > 4 ? [lindex $argv 4] : "none far evaluated"}]
set order  [expr {$argc > 5 ? [lindex $argv 5] : "joint"}]
set process [expr {$argc > 6 ? [lindex $argv 6] : "fresh"}]
if {$order ni {joint after}} { error "far-pairs.tcl: order must be joint or after, not \"$order\"" }
if {$process ni {fresh same}} { error "far-pairs.tcl: process must be fresh or same, not \"$process\"" }

source [file join [file dirname [info script]] cpu-time.tcl]

proc pairs {j mode} {
  set a [expr {1000 * $j}]; set b [expr {1000 * $j + 100}]
  set opts [list -K 1.0e7 -mu_s 0.3]
  if {$mode eq "far"} { lappend opts -search 0.05 }
  lappend ::pairTags {*}[pounding [expr {100000 + 8 * $j}] \
      -side1 [list [expr {$a+1}] [expr {$a+2}] [expr {$a+3}] [expr {$a+4}]] [list [expr {$a+1}] [expr {$a+2}] [expr {$a+3}] [expr {$a+4}]] \
      -side2 [list [expr {$b+1}] [expr {$b+2}] [expr {$b+3}] [expr {$b+4}]] [list [expr {$b+1}] [expr {$b+4}] [expr {$b+3}] [expr {$b+2}]] {*}$opts]
}

proc build {J mode order} {
  wipe
  set ::pairTags {}
  set defined [expr {$mode eq "removed" ? "far" : $mode}]
  model basic -ndm 3 -ndf 3
  uniaxialMaterial Elastic 1 1.0e5
  set ele 0
  for {set j 0} {$j < $J} {incr j} {
    set x0 [expr {10.0 * $j}]
    foreach side {0 1} {
      set x [expr {$x0 + 0.2 * $side}]
      set i 0
      foreach {y z} {-1 -0.5  1 -0.5  1 0.5  -1 0.5} {
        incr i
        set n [expr {1000 * $j + 100 * $side + $i}]
        node $n $x $y $z
        node [expr {$n + 50}] $x $y $z
        fix [expr {$n + 50}] 1 1 1
        mass $n 1.0 1.0 1.0
        element zeroLength [incr ele] [expr {$n + 50}] $n -mat 1 1 1 -dir 1 2 3
      }
    }
    if {$mode ne "none" && $order eq "joint"} { pairs $j $defined }
  }
  if {$mode ne "none" && $order eq "after"} {
    for {set j 0} {$j < $J} {incr j} { pairs $j $defined }
  }
  if {$mode eq "removed"} { foreach tag $::pairTags { remove element $tag } }
  timeSeries Trig 1 0.0 100.0 0.5 -factor 0.5
  pattern UniformExcitation 1 1 -accel 1
  constraints Plain; numberer RCM; system UmfPack
  test NormDispIncr 1e-8 20; algorithm Newton
  integrator Newmark 0.5 0.25; analysis Transient
}

# One run: {cpu_s iterations elementUpdates patternChanges disp_node1 farTests}.
proc runOnce {J steps mode order} {
  build $J $mode $order
  set t0 [cpuSeconds]
  set rc [analyze $steps 0.005]
  set t [expr {[cpuSeconds] - $t0}]
  if {$rc != 0} { error "$mode: analyze returned $rc" }
  set st [analysisStatistics]
  set cs [contactStepping]
  return [list $t [dict get $st iterations] [dict get $st elementUpdates] \
      [dict get $cs patternChanges] [nodeDisp 1 1] [dict get $cs farTests]]
}

if {$process eq "same" && $repeat == 1 && [llength $modes] == 1 && $csv eq "-"} {
  # a child of the "fresh" driver below: one run, one line
  puts [list RESULT {*}[runOnce $J $steps $modes $order]]
  exit 0
}

proc median {values} {
  set v [lsort -real $values]
  set n [llength $v]
  return [expr {$n % 2 ? [lindex $v [expr {$n / 2}]] : 0.5 * ([lindex $v [expr {$n / 2 - 1}]] + [lindex $v [expr {$n / 2}]])}]
}

foreach mode $modes { set times($mode) {} }
for {set r 0} {$r < $repeat} {incr r} {
  foreach mode $modes {
    if {$process eq "fresh"} {
      set out [exec [info nameofexecutable] [info script] $J $steps 1 - $mode $order same]
      set result {}
      foreach line [split $out \n] {
        if {[lindex $line 0] eq "RESULT"} { set result [lrange $line 1 end] }
      }
      if {$result eq ""} { error "$mode: no result from the child process: $out" }
    } else {
      set result [runOnce $J $steps $mode $order]
    }
    lappend times($mode) [lindex $result 0]
    set last($mode) $result
  }
}

set rows {}
puts [format "%-9s %6s %6s %9s %9s %10s %12s %8s %8s %8s %12s" mode pairs steps cpu_s median_s us/step iterations elemUpd patterns farTests peak_disp]
foreach mode $modes {
  set best [tcl::mathfunc::min {*}$times($mode)]
  set med [median $times($mode)]
  lassign $last($mode) t iterations updates patterns d farTests
  set pairs [expr {$mode in {none removed} ? 0 : 8 * $J}]
  puts [format "%-9s %6d %6d %9.2f %9.3f %10.1f %12d %8d %8s %8s %12.6e" $mode $pairs $steps $best $med [expr {1e6 * $best / $steps}] \
      $iterations $updates $patterns $farTests $d]
  lappend rows [list $mode $pairs $steps $best $iterations $updates $d $med]
}
set base [lindex $rows 0 3]
set others [expr {[lindex $rows 0 0] eq "none" && $base > 0 && [lindex $rows 0 7] > 0 ? [lrange $rows 1 end] : {}}]
foreach r $others {
  puts [format "%s: %+.1f %% CPU time against no pairs (smallest; medians %+.1f %%); same displacement of node 1: %s" \
      [lindex $r 0] [expr {100.0 * ([lindex $r 3] - $base) / $base}] \
      [expr {100.0 * ([lindex $r 7] - [lindex $rows 0 7]) / [lindex $rows 0 7]}] \
      [expr {[lindex $r 6] == [lindex $rows 0 6] ? "yes" : "no ([lindex $r 6])"}]]
}
if {$csv ne "" && $csv ne "-"} {
  set f [open $csv w]
  puts $f "mode,pairs,steps,cpu_s,iterations,element_updates,disp_node1,median_cpu_s"
  foreach r $rows { puts $f [join $r ,] }
  close $f
}
