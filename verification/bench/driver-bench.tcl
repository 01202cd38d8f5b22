# SPDX-License-Identifier: MIT
# Benchmarks of the analysis driver. Run: dabs verification/bench/driver-bench.tcl ?csv?
# Prints a table and writes a CSV (default driver-bench.csv in the working directory).
#  1. a linear 3D frame of about 2,000 dofs, 4,000 Newmark steps with algorithm Linear;
#  2. the same frame with elastic-plastic zeroLength hinges at the column bases, algorithm Newton
#     (400 steps: every iteration refactorises);
#  3. building a 10,000-node model from a Tcl loop.
# Every time is paired with its error: the peak roof displacement against a run with a 4 times
# smaller step (for 1 and 2). Times are medians of `repeat` runs measured in this one process.
set csv [expr {$argc > 0 ? [lindex $argv 0] : "driver-bench.csv"}]
set repeat 3

proc buildFrame {hinges} {
  wipe
  model basic -ndm 3 -ndf 6
  set nx 4; set ny 4; set nz 13; set span 6.0; set h 3.5
  set E 2.0e8; set G 7.7e7; set A 0.05; set Iz 1.2e-3; set Iy 8.0e-4; set J 1.0e-4
  uniaxialMaterial Elastic 1 1.0e12
  uniaxialMaterial Steel01 2 800.0 2.0e5 0.02   ;# base hinge: My = 800 kNm
  for {set k 0} {$k <= $nz} {incr k} {
    for {set i 0} {$i <= $nx} {incr i} {
      for {set j 0} {$j <= $ny} {incr j} {
        set tag [expr {10000*$k + 100*$i + $j + 1}]
        node $tag [expr {$i*$span}] [expr {$j*$span}] [expr {$k*$h}]
        if {$k == 0} {
          fix $tag 1 1 1 1 1 1
          if {$hinges} {
            node [expr {$tag + 5000}] [expr {$i*$span}] [expr {$j*$span}] 0.0
            element zeroLength [expr {900000 + $tag}] $tag [expr {$tag + 5000}] -mat 1 1 1 1 2 2 -dir 1 2 3 6 4 5
          }
        } else { mass $tag 40.0 40.0 0.0 0.0 0.0 0.0 }
      }
    }
  }
  geomTransf Linear 1 1 0 0
  geomTransf Linear 2 0 0 1
  set e 0
  for {set k 1} {$k <= $nz} {incr k} {
    for {set i 0} {$i <= $nx} {incr i} {
      for {set j 0} {$j <= $ny} {incr j} {
        set n [expr {10000*$k + 100*$i + $j + 1}]
        set below [expr {$n - 10000}]
        if {$k == 1 && $hinges} { set below [expr {$below + 5000}] }
        element elasticBeamColumn [incr e] $below $n $A $E $G $J $Iy $Iz 1
        if {$i < $nx} { element elasticBeamColumn [incr e] $n [expr {$n + 100}] $A $E $G $J $Iy $Iz 2 }
        if {$j < $ny} { element elasticBeamColumn [incr e] $n [expr {$n + 1}] $A $E $G $J $Iy $Iz 2 }
      }
    }
  }
  rayleigh 0.2 0.0 0.002 0.0
  timeSeries Trig 1 0.0 4.0 1.0 -factor 3.0
  pattern UniformExcitation 1 1 -accel 1
  return [expr {10000*$nz + 100*$nx + $ny + 1}]
}

proc runFrame {hinges algorithm dt steps} {
  set roof [buildFrame $hinges]
  constraints Transformation; numberer RCM; system SparseSYM
  test NormDispIncr 1e-10 20
  algorithm {*}$algorithm
  integrator Newmark 0.5 0.25
  analysis Transient
  set peak 0.0
  set t0 [clock microseconds]
  set status 0
  # Run in chunks so the peak can be tracked without a recorder.
  set chunk [expr {max(1, $steps/400)}]
  for {set s 0} {$s < $steps && $status == 0} {incr s $chunk} {
    set status [analyze $chunk $dt]
    set peak [expr {max($peak, abs([nodeDisp $roof 1]))}]
  }
  set seconds [expr {([clock microseconds] - $t0)*1e-6}]
  set stats [analysisStatistics]
  set dofs [expr {6*([llength [getNodeTags]] - 25)}]
  return [list $seconds $peak $status $dofs [dict get $stats iterations] [dict get $stats factorizations] [dict get $stats steps]]
}

proc median {values} {
  set s [lsort -real $values]
  return [lindex $s [expr {[llength $s]/2}]]
}

set rows {}
# The hinged frame refactorises at every Newton iteration, so it runs fewer steps.
foreach {name hinges algorithm steps} {linear-frame 0 Linear 4000 hinged-frame-newton 1 Newton 400} {
  set dt 0.005
  set times {}
  for {set r 0} {$r < $repeat} {incr r} {
    lassign [runFrame $hinges $algorithm $dt $steps] seconds peak status dofs iterations factorizations done
    lappend times $seconds
  }
  lassign [runFrame $hinges $algorithm [expr {$dt/4}] [expr {4*$steps}]] refSeconds refPeak
  set t [median $times]
  lappend rows [list $name $dofs $steps $t [expr {$steps/$t}] [expr {1000.0*$t/$iterations}] \
      [expr {double($iterations)/$steps}] [expr {double($factorizations)/$steps}] $peak $refPeak \
      [expr {abs($peak - $refPeak)/$refPeak}] $status]
}

# Model building from a Tcl loop: 10,000 nodes (and 9,999 elastic beams between them).
set times {}
for {set r 0} {$r < $repeat} {incr r} {
  wipe
  model basic -ndm 3 -ndf 6
  geomTransf Linear 1 0 0 1
  set t0 [clock microseconds]
  for {set i 1} {$i <= 10000} {incr i} { node $i [expr {$i*1.0}] 0.0 0.0 }
  set nodeSeconds [expr {([clock microseconds] - $t0)*1e-6}]
  for {set i 1} {$i < 10000} {incr i} { element elasticBeamColumn $i $i [expr {$i+1}] 1.0 1.0 1.0 1.0 1.0 1.0 1 }
  lappend times [list $nodeSeconds [expr {([clock microseconds] - $t0)*1e-6}]]
}
set nodeTime [median [lmap x $times {lindex $x 0}]]
set allTime [median [lmap x $times {lindex $x 1}]]

puts [format "%-20s %6s %6s %9s %9s %10s %8s %9s %11s %11s %9s" case dofs steps "wall(s)" steps/s "ms/iter" iter/step fact/step "peak(m)" "ref peak" "rel err"]
foreach row $rows {
  lassign $row name dofs steps t rate msIter iterStep factStep peak ref err status
  puts [format "%-20s %6d %6d %9.3f %9.1f %10.3f %8.2f %9.3f %11.6f %11.6f %9.2e" $name $dofs $steps $t $rate $msIter $iterStep $factStep $peak $ref $err]
}
puts [format "model building: 10,000 nodes in %.3f s; 10,000 nodes + 9,999 elastic beams in %.3f s (median of %d)" $nodeTime $allTime $repeat]
set f [open $csv w]
puts $f "case,dofs,steps,wall_s,steps_per_s,ms_per_iteration,iterations_per_step,factorizations_per_step,peak_m,reference_peak_m,relative_error"
foreach row $rows { puts $f [join [lrange $row 0 10] ,] }
puts $f "build-10000-nodes,60000,0,$nodeTime,,,,,,,"
puts $f "build-10000-nodes-and-beams,60000,0,$allTime,,,,,,,"
close $f
