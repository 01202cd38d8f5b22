# SPDX-License-Identifier: MIT
# `threads n`: element state determination on n threads gives the same numbers, bit for bit, as
# one thread (elements share nothing, and the assembly adds their contributions in one order).
# The 10-span bridge of the OpenSees speed benchmark (fiber piers, nonlinear bearings, gap
# springs; its sparse LDL^T is split into two halves that two threads factorise and solve at
# once) runs 300 steps of the Takatori record with 1 and with 2 threads; every recorded value
# is compared to the last digit (17 significant digits), together with the work counts. The
# automatic choice (`threads auto`, the default) runs its first steps on one and on every
# available thread in turn before it settles (ThreadChoice): the same numbers again.
source [file join [file dirname [info script]] .. lib check.tcl]
set bench [file join [file dirname [info script]] .. bench opensees bridge.tcl]

proc runWith {threads out} {
  threads $threads
  set ::argv [list 10 300 $out]
  set ::argc 3
  uplevel #0 [list source $::bench]
  set stats [analysisStatistics]
  wipe
  return $stats
}
proc readAll {f} {
  set ch [open $f r]
  set text [read $ch]
  close $ch
  return $text
}

checkAbs "threads with no argument returns the count in force (auto, before any step: 1)" \
    [threads] 1 0
set one [runWith 1 out-1]
set two [runWith 2 out-2]
set auto [runWith auto out-auto]
checkTrue "auto: analysisStatistics reports the count in force ([dict get $auto threads])" \
    [expr {[dict get $auto threads] >= 1}]
if {[dict exists $auto threadRatio]} {
  checkTrue "auto measured a ratio ([dict get $auto threadRatio]) and chose by it" \
      [expr {[dict get $auto threadRatio] > 0.0 &&
             ([dict get $auto threads] > 1) == ([dict get $auto threadRatio] <= 0.95)}]
}
threads 1
foreach key {iterations factorizations elementUpdates materialUpdates} {
  checkAbs "$key with 2 threads equals 1 thread" [dict get $two $key] [dict get $one $key] 0
  checkAbs "$key with auto equals 1 thread" [dict get $auto $key] [dict get $one $key] 0
}
foreach f {girder-disp.out pier-disp.out pier-force.out} {
  # The bench script records 17 significant digits: the files are the numbers.
  set same [expr {[readAll out-1/$f] eq [readAll out-2/$f]}]
  checkAbs "$f identical with 1 and 2 threads" $same 1 0
  set same [expr {[readAll out-1/$f] eq [readAll out-auto/$f]}]
  checkAbs "$f identical with 1 thread and auto" $same 1 0
}
checkAbs "every step converged" [expr {[dict get $one steps] == 300 && [dict get $one failedSteps] == 0}] 1 0
foreach bad {0 -1 257 abc} {
  checkAbs "threads $bad is an error" [catch {threads $bad}] 1 0
}
checkTrue "threads auto 2 is an error" [catch {threads auto 2}]
checkTrue "threads auto returns a count" [string is integer -strict [threads auto]]
finish
