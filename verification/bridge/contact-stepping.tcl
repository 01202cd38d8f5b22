# SPDX-License-Identifier: MIT
# Event-located contact stepping in the driver (`contactStepping`) against the Tcl procedure the
# case study used before it (kept below as it was, nextStepLength): a two-span version of the
# bridge (bridge.tcl with nSpans 2, one joint of 8 pounding pairs) under the first 8 s of the
# Takatori record, once stepped by the procedure (`analyze 1 $h` per step) and once by
# `analyze $nSteps $dt` with the driver's stepping. Both must take the same steps (same times)
# and give the same joint gap, pounding force and bearing strain at every step; the procedure
# cuts a step at each pair's predicted contact in turn while the driver takes the shortest cut,
# which for the joint's eight pairs (one flat face) is the same step.
set ::bridgeLibraryOnly 1
source [file join [file dirname [info script]] bridge.tcl]
set nSpans 2
set endCondition free   ;# the one joint only (the procedure below watches the joints' pairs)
set duration 8.0
set dt 0.01

set failures 0
proc check {name ok {detail ""}} {
  if {$ok} { puts "PASSED $name" } else { puts "FAILED $name $detail"; incr ::failures }
}

# --- the procedure as the case study had it ------------------------------------------------
proc nextStepLength {remaining} {
  upvar #0 contactGapLast last contactStepLast lastH
  set h $remaining
  set near 0
  set hMin [expr {0.01 * $::contactDt}]
  foreach list $::poundingEles {
    foreach e $list {
      set gap [eleResponse $e gap]
      if {$gap < 0.0 || [eleResponse $e status] != 0} { set near 1 }
      if {[info exists last($e)] && $lastH > 0.0 && $gap > 0.0 && $gap < $last($e)} {
        set tClose [expr {$gap * $lastH / ($last($e) - $gap)}]
        if {$tClose <= $::contactLookahead * $remaining} { set near 1 }
        if {$tClose < $h} { set h [expr {max($::contactOvershoot * $tClose, $hMin)}] }
      }
      set last($e) $gap
    }
  }
  if {$near} { set h [expr {min($h, $::contactDt)}] }
  if {$remaining - $h < $hMin} { set h $remaining }
  set lastH $h
  return $h
}

# Model and analysis as runCase sets them up.
proc setUp {} {
  buildModel pound
  if {[applyDeadLoad] != 0} { error "dead load analysis failed" }
  wipeAnalysis
  applyMotion record 1.0
  constraints Transformation
  numberer RCM
  system SparseSYM
  test NormDispIncr $::defaultTol 30
  algorithm Newton
  integrator Newmark 0.5 0.25
  analysis Transient -numSubLevels 4 -numSubSteps 4
}
# One row per committed step: time, longitudinal joint gap, pounding force of the joint, shear
# strain of the bearings of G2 over PC2 (the largest over the end's bearings).
proc sample {} {
  lassign $::girderEndNodes g1s g1e g2s g2e
  set f 0.0
  foreach e [lindex $::poundingEles 0] { set f [expr {$f + [lindex [eleResponse $e contactForce] 0]}] }
  lappend ::rows [list [getTime %.17g] [expr {[nodeDisp $g2s 1] - [nodeDisp $g1e 1]}] $f [tcl::mathfunc::max {*}[lmap e [endBearings [bearingTag 2 12]] {eleResponse $e shearStrain}]]]
}

# Run 1: the procedure
setUp
set ::rows {}
array unset ::contactGapLast
set ::contactStepLast 0.0
set nSteps [expr {int(round($duration / $dt))}]
set rc 0
for {set step 1} {$step <= $nSteps && $rc == 0} {incr step} {
  set tEnd [expr {$step * $dt}]
  while {$rc == 0} {
    set remaining [expr {$tEnd - [getTime %.17g]}]
    if {$remaining <= 1e-9 * $dt} { break }
    set rc [analyze 1 [nextStepLength $remaining]]
    if {$rc == 0} { sample }
  }
}
check "the procedure's run completes" [expr {$rc == 0}] "analyze returned $rc"
set tclRows $::rows

# Run 2: the driver
setUp
set ::rows {}
contactStepping -maxStep $contactDt -lookAhead $contactLookahead -overshoot $contactOvershoot -eachStep sample
set rc [analyze $nSteps $dt]
check "the driver's run completes" [expr {$rc == 0}] "analyze returned $rc"
set driverRows $::rows
set state [contactStepping]
check "contactStepping reports the joint's 8 pairs" [expr {[dict get $state pairs] == 8}] $state

check "same number of steps ([llength $tclRows])" [expr {[llength $tclRows] == [llength $driverRows]}] \
    "procedure [llength $tclRows], driver [llength $driverRows]"
check "contact steps are taken (more steps than output steps)" [expr {[llength $driverRows] > $nSteps + 100}] \
    "[llength $driverRows] steps for $nSteps output steps"
check "the driver counts its contact steps" [expr {[dict get $state contactSteps] > 100}] $state
# Largest differences, relative to the largest magnitude of each quantity over the run.
set worst {0.0 0.0 0.0 0.0}
set scale {1.0 0.0 0.0 0.0}
foreach r $tclRows {
  foreach i {1 2 3} { lset scale $i [expr {max([lindex $scale $i], abs([lindex $r $i]))}] }
}
set n [expr {min([llength $tclRows], [llength $driverRows])}]
for {set k 0} {$k < $n} {incr k} {
  set a [lindex $tclRows $k]; set b [lindex $driverRows $k]
  foreach i {0 1 2 3} {
    lset worst $i [expr {max([lindex $worst $i], abs([lindex $a $i] - [lindex $b $i]) / max([lindex $scale $i], 1e-300))}]
  }
}
puts "largest differences (time s; gap, force, strain relative to their peaks): $worst"
puts "peaks: gap [lindex $scale 1] m, force [lindex $scale 2] kN, strain [lindex $scale 3]"
check "pounding happens in the run (force > 0)" [expr {[lindex $scale 2] > 0.0}]
check "same step times (within 1e-9 s)" [expr {[lindex $worst 0] <= 1e-9}] [lindex $worst 0]
foreach i {1 2 3} what {"joint gap" "pounding force" "bearing strain"} {
  check "same $what at every step (within 1e-6 of its peak)" [expr {[lindex $worst $i] <= 1e-6}] [lindex $worst $i]
}

# Bad input is named.
foreach {args expect} {{-maxStep 0} maxStep {-maxStep -1} maxStep {-overshoot 0.5} overshoot {-lookAhead -1} lookAhead {-maxStep abc} maxStep {-bogus 1} bogus} {
  set ok [catch {contactStepping {*}$args} msg]
  check "contactStepping $args is an error naming $expect" [expr {$ok && [string match *$expect* $msg]}] $msg
}
contactStepping -off
check "-off turns it off" [expr {[dict get [contactStepping] on] == 0}]
if {$failures > 0} { exit 1 }
