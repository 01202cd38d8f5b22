# SPDX-License-Identifier: MIT
# Deferred faces: within one `analyze` call, the sleeping pairs against a girder-end face that
# nobody reads at every step are left alone (no far test, no commit) until the motion of their
# nodes could have brought one of them to its search distance. The results must be those of the
# far test of every step, to the bit: a face is tested exactly when its horizon is reached, so a
# pair wakes at the same step. Three joints, each two girder-end faces (2 x 1 m and 3 x 2 m, the
# second four times as heavy) 0.05 m apart, shaken along the row so that they close, pound and
# open again. The faces' nodes are carried three ways: each on its own springs; tied to a centre
# node on springs by equalDOF (Transformation); and tied by rigidLink beam (6 dofs) to a deck
# node 6 m to the side that also rocks about the vertical axis, so its rotation moves the corners
# by lever arms of up to 7.5 m, which the motion bound must count (a bound that took the
# rotation's change as a corner's fails here).
#
# Run A: `analyze 40` twenty times (face tests deferred). Run B: `analyze 1` 800 times (one step
# defers nothing: every pair is tested at every step, as before deferring existed). Run C: as A
# with an Element recorder on every pair (a recorded pair is read at every step, so its face's
# test is never deferred).
# After every 40 steps each run prints every node's displacement and velocity and every pair's
# gap, contact force, impulse, dissipated energy, status and slip at 17 digits: the three must
# print the same lines, and A must have made fewer far tests than B and C.
set failures 0
proc check {name ok {detail ""}} {
  if {$ok} { puts "PASSED $name" } else { puts "FAILED $name $detail"; incr ::failures }
}

proc build {carrier search mu {integrator {Newmark 0.5 0.25}}} {
  wipe
  if {$carrier eq "rigidLink"} { model basic -ndm 3 -ndf 6 } else { model basic -ndm 3 -ndf 3 }
  uniaxialMaterial Elastic 1 100.0
  uniaxialMaterial Elastic 2 400.0
  set ele 0
  set ::pairs {}
  for {set j 0} {$j < 3} {incr j} {
    foreach side {0 1} m {1.0 4.0} w {1.0 1.5} d {0.5 1.0} {
      set x [expr {10.0 * $j + 0.05 * $side}]
      set corners {}
      set i 0
      foreach {y z} [list -$w -$d $w -$d $w $d -$w $d] {
        set n [expr {1000 * $j + 100 * $side + [incr i]}]
        node $n $x $y $z
        lappend corners $n
        if {$carrier eq "springs"} {
          node [expr {$n + 50}] $x $y $z
          fix [expr {$n + 50}] 1 1 1
          mass $n $m $m $m
          element zeroLength [incr ele] [expr {$n + 50}] $n -mat 1 1 1 -dir 1 2 3
        }
      }
      if {$carrier ne "springs"} {
        set c [expr {1000 * $j + 100 * $side + 10}]
        # with rigidLink, the centre is a deck node 6 m to the side of the girder ends, so a
        # rotation about the vertical moves the corners along the row by 4.5 to 7.5 times it
        set xc [expr {$carrier eq "rigidLink" ? $x - 4.0 + 8.0 * $side : $x}]
        set yc [expr {$carrier eq "rigidLink" ? 6.0 : 0.0}]
        node $c $xc $yc 0.0
        node [expr {$c + 50}] $xc $yc 0.0
        if {$carrier eq "rigidLink"} {
          fix [expr {$c + 50}] 1 1 1 1 1 1
          mass $c $m $m $m $m $m $m
          element zeroLength [incr ele] [expr {$c + 50}] $c -mat 2 2 2 2 2 2 -dir 1 2 3 4 5 6
          foreach n $corners { rigidLink beam $c $n }
        } else {
          fix [expr {$c + 50}] 1 1 1
          mass $c $m $m $m
          element zeroLength [incr ele] [expr {$c + 50}] $c -mat 2 2 2 -dir 1 2 3
          foreach n $corners { equalDOF $c $n 1 2 3 }
        }
      }
    }
    set a [expr {1000 * $j}]
    set b [expr {1000 * $j + 100}]
    set faceA [list [expr {$a + 1}] [expr {$a + 2}] [expr {$a + 3}] [expr {$a + 4}]]
    set faceB [list [expr {$b + 1}] [expr {$b + 2}] [expr {$b + 3}] [expr {$b + 4}]]
    set opts [list -K 1.0e4 -search $search]
    if {$mu > 0} { lappend opts -mu_s $mu }
    # each face's outward normal points at the other girder end
    lappend ::pairs {*}[pounding [expr {100000 + 8 * $j}] -side1 $faceA $faceA \
        -side2 $faceB [list [expr {$b + 1}] [expr {$b + 4}] [expr {$b + 3}] [expr {$b + 2}]] {*}$opts]
  }
  if {$carrier eq "rigidLink"} {
    # rocking about the vertical axis alone: the corners move along the row by the deck
    # nodes' rotations times their lever arms
    timeSeries Trig 2 0.0 100.0 0.6 -factor 0.5
    pattern UniformExcitation 2 6 -accel 2
  } else {
    timeSeries Trig 1 0.0 100.0 0.8 -factor 3.0
    pattern UniformExcitation 1 1 -accel 1
  }
  if {$carrier eq "springs"} { constraints Plain } else { constraints Transformation }
  numberer RCM
  system UmfPack
  test NormDispIncr 1e-9 30
  algorithm Newton
  integrator {*}$integrator
  analysis Transient
}

# Every node's displacement and velocity and every pair's responses, at 17 digits.
proc snapshot {} {
  set lines {}
  foreach n [getNodeTags] {
    set values [concat [nodeDisp $n] [nodeVel $n]]
    lappend lines "node $n [lmap v $values { format %.17g $v }]"
  }
  foreach e $::pairs {
    set values {}
    foreach q {gap contactForce impulse dissipatedEnergy status slip} {
      lappend values {*}[eleResponse $e $q]
    }
    lappend lines "pair $e [lmap v $values { format %.17g $v }]"
  }
  return $lines
}

# mode: defer (analyze 40 at a time), step (analyze 1), recorded (defer, with an Element recorder
# on every pair). Returns {lines farTests stats}.
proc run {carrier search mu mode {integrator {Newmark 0.5 0.25}}} {
  build $carrier $search $mu $integrator
  set recorderFile ""
  if {$mode eq "recorded"} {
    close [file tempfile recorderFile deferred-faces.out]
    recorder Element -file $recorderFile -ele {*}$::pairs gap
  }
  try {
    set lines {}
    for {set chunk 0} {$chunk < 20} {incr chunk} {
      if {$mode eq "step"} {
        for {set k 0} {$k < 40} {incr k} {
          if {[analyze 1 0.005] != 0} { return [list [concat $lines fail] 0 {}] }
        }
      } elseif {[analyze 40 0.005] != 0} {
        return [list [concat $lines fail] 0 {}]
      }
      lappend lines {*}[snapshot]
    }
    set stats [analysisStatistics]
    set cs [contactStepping]
    set summary [list [dict get $stats steps] [dict get $stats iterations] \
        [dict get $stats elementUpdates] [dict get $cs patternChanges] [dict get $cs redoneSteps]]
    return [list $lines [dict get $cs farTests] $summary]
  } finally {
    if {$recorderFile ne ""} {
      remove recorders
      file delete $recorderFile
    }
  }
}

foreach {carrier search mu} {
  springs 0.01 0.0  springs 0.001 0.0  springs 0.01 0.3
  equalDOF 0.01 0.0  rigidLink 0.01 0.0  rigidLink 0.001 0.0  rigidLink 0.01 0.3
} {
  set name "$carrier, search $search, mu $mu"
  lassign [run $carrier $search $mu step] stepLines stepTests stepSummary
  lassign [run $carrier $search $mu defer] deferLines deferTests deferSummary
  lassign [run $carrier $search $mu recorded] recLines recTests recSummary
  lassign $stepSummary steps iterations updates changes redone
  puts "$name: $steps steps, $iterations iterations, $changes pattern changes, $redone steps redone;\
      far tests $stepTests (analyze 1), $deferTests (deferred), $recTests (recorded)"
  check "$name: the run completes and the faces pound (pattern changes)" \
      [expr {[lindex $stepLines end] ne "fail" && $changes >= 4}] "$changes"
  set differ 0
  foreach a $stepLines b $deferLines { if {$a ne $b} { incr differ } }
  check "$name: deferred face tests give the same displacements, velocities and pair responses" \
      [expr {$differ == 0 && [llength $stepLines] == [llength $deferLines]}] "$differ lines differ"
  check "$name: and the same iterations, element updates, pattern changes and redone steps" \
      [expr {$stepSummary eq $deferSummary}] "$stepSummary / $deferSummary"
  check "$name: deferred face tests make fewer far tests" [expr {$deferTests < 0.8 * $stepTests}] \
      "$deferTests against $stepTests"
  set differ 0
  foreach a $stepLines b $recLines { if {$a ne $b} { incr differ } }
  check "$name: recorded pairs give the same results and never deferred" \
      [expr {$differ == 0 && $recSummary eq $stepSummary && $recTests == $stepTests}] \
      "$differ lines differ, far tests $recTests"
}
# HHT (alpha 0.9): the nodes are at the alpha-weighted positions when the sleepers are tested,
# and at t(n+1) when the step is committed, so a deferred pair's gap, formed at the committed
# positions, would not be the one the test of every step leaves: face tests are not deferred, and the two
# runs are the same to the bit, with the same far tests.
set name "springs, search 0.001, HHT"
lassign [run springs 0.001 0.0 step {HHT 0.9}] stepLines stepTests stepSummary
lassign [run springs 0.001 0.0 defer {HHT 0.9}] deferLines deferTests deferSummary
set differ 0
foreach a $stepLines b $deferLines { if {$a ne $b} { incr differ } }
puts "$name: [lindex $stepSummary 3] pattern changes; far tests $stepTests (analyze 1),\
    $deferTests (analyze 40)"
check "$name: no face test deferred, and the results are the same to the bit" \
    [expr {$differ == 0 && [llength $stepLines] == [llength $deferLines] &&
           $stepSummary eq $deferSummary && $stepTests == $deferTests &&
           [lindex $stepSummary 3] >= 4}] "$differ lines differ, far tests $deferTests"
if {$failures > 0} { exit 1 }
