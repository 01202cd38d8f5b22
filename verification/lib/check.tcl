# SPDX-License-Identifier: MIT
# Shared helpers for verification scripts: each check prints PASSED or FAILED with the values and
# the tolerance; `finish` prints the tally and exits 1 when any check failed (ctest reads the code).
#
#   source [file join [file dirname [info script]] .. lib check.tcl]
#   check "cantilever tip deflection PL^3/3EI" $computed $expected 1e-9
#   checkAbs "velocity after impact" $v $expected 1e-6
#   finish

namespace eval ::verify {
  variable passed 0
  variable failed 0
  # The project's verification folder: data/ holds the ground-motion records, opensees/ OpenSees'
  # reference inputs and results.
  variable verification [file normalize [file join [file dirname [info script]] ..]]
}

# Relative check: |computed - expected| <= tol * max(|expected|, tiny).
proc check {name computed expected tol} {
  set scale [expr {max(abs($expected), 1e-300)}]
  set err [expr {abs($computed - $expected) / $scale}]
  if {$err <= $tol} {
    incr ::verify::passed
    puts [format "PASSED  %-60s computed %.10g expected %.10g (rel err %.2e <= %.1e)" $name $computed $expected $err $tol]
  } else {
    incr ::verify::failed
    puts [format "FAILED  %-60s computed %.10g expected %.10g (rel err %.2e > %.1e)" $name $computed $expected $err $tol]
  }
}

# Absolute check: |computed - expected| <= tol.
proc checkAbs {name computed expected tol} {
  set err [expr {abs($computed - $expected)}]
  if {$err <= $tol} {
    incr ::verify::passed
    puts [format "PASSED  %-60s computed %.10g expected %.10g (abs err %.2e <= %.1e)" $name $computed $expected $err $tol]
  } else {
    incr ::verify::failed
    puts [format "FAILED  %-60s computed %.10g expected %.10g (abs err %.2e > %.1e)" $name $computed $expected $err $tol]
  }
}

# Boolean check.
proc checkTrue {name condition} {
  if {$condition} {
    incr ::verify::passed
    puts [format "PASSED  %s" $name]
  } else {
    incr ::verify::failed
    puts [format "FAILED  %s" $name]
  }
}

# Path of a ground-motion record in verification/data.
proc recordPath {name} { return [file join $::verify::verification data $name] }
# Path of an OpenSees reference input or result in verification/opensees.
proc openseesReference {name} { return [file join $::verify::verification opensees $name] }
# The same files under the layout of the shared data folder the project once read
# (`sharedData ground-motions X`, `sharedData reference opensees X`), for scripts written then.
proc sharedData {args} {
  switch -- [lindex $args 0] {
    ground-motions { return [recordPath [lindex $args end]] }
    reference { return [openseesReference [lindex $args end]] }
  }
  error "sharedData: no project copy of $args"
}

# Prints the tally and exits with 1 when a check failed.
proc finish {} {
  puts "$::verify::passed passed, $::verify::failed failed"
  exit [expr {$::verify::failed > 0 ? 1 : 0}]
}
