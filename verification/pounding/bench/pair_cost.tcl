# SPDX-License-Identifier: MIT
# Cost of contact pairs that never touch (only what the scene needs): a row of J girder
# joints, each two girder-end faces of 4 nodes on springs, shaken along the row; the same model is
# timed without contact, with `pounding` pairs (8 per joint) beyond their search distance, and with
# the pairs but no search distance (every pair evaluated, none touching). Not a pass/fail test:
# prints CSV (case, pairs, steps, wall seconds, microseconds per step).
#
#   dabs verification/pounding/bench/pair_cost.tcl ?joints? ?steps?
set J     [expr {$argc > 0 ? [lindex $argv 0] : 50}]
set steps [expr {$argc > 1 ? [lindex $argv 1] : 400}]

proc build {J mode} {
  wipe
  model basic -ndm 3 -ndf 3
  uniaxialMaterial Elastic 1 1.0e5
  set ele 0
  for {set j 0} {$j < $J} {incr j} {
    set x0 [expr {10.0*$j}]
    foreach side {0 1} {
      set x [expr {$x0 + 0.2*$side}]
      set i 0
      foreach {y z} {-1 -0.5  1 -0.5  1 0.5  -1 0.5} {
        incr i
        set n [expr {1000*$j + 100*$side + $i}]
        set g [expr {$n + 50}]
        node $n $x $y $z
        node $g $x $y $z
        fix $g 1 1 1
        mass $n 1.0 1.0 1.0
        element zeroLength [incr ele] $g $n -mat 1 1 1 -dir 1 2 3
      }
    }
    if {$mode ne "none"} {
      set a [expr {1000*$j}]
      set b [expr {1000*$j + 100}]
      set opts [list -K 1.0e7 -mu_s 0.3]
      if {$mode eq "search"} { lappend opts -search 0.05 }
      pounding [expr {100000 + 8*$j}] -side1 [list [expr {$a+1}] [expr {$a+2}] [expr {$a+3}] [expr {$a+4}]] \
          [list [expr {$a+1}] [expr {$a+2}] [expr {$a+3}] [expr {$a+4}]] \
          -side2 [list [expr {$b+1}] [expr {$b+2}] [expr {$b+3}] [expr {$b+4}]] \
          [list [expr {$b+1}] [expr {$b+4}] [expr {$b+3}] [expr {$b+2}]] {*}$opts
    }
  }
  timeSeries Trig 1 0.0 100.0 0.5 -factor 0.5
  pattern UniformExcitation 1 1 -accel 1
  constraints Plain; numberer RCM; system UmfPack
  test NormDispIncr 1e-8 20; algorithm Newton
  integrator Newmark 0.5 0.25; analysis Transient
}

puts "case,pairs,steps,seconds,us_per_step"
foreach mode {none search nosearch} {
  build $J $mode
  set t0 [clock microseconds]
  set rc [analyze $steps 0.005]
  set t1 [clock microseconds]
  set pairs [expr {$mode eq "none" ? 0 : 8*$J}]
  puts [format "%s,%d,%d,%.3f,%.1f%s" $mode $pairs $steps [expr {($t1-$t0)*1e-6}] [expr {double($t1-$t0)/$steps}] \
      [expr {$rc == 0 ? "" : " (analyze returned $rc)"}]]
}
