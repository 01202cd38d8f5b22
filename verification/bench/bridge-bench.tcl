# SPDX-License-Identifier: MIT
# Benchmark of the bridge case study: wall time of each case at the default settings,
# with equations, steps, iterations and factorisations; the target is under 10 s per case on a
# 2-core machine.
#
#   dabs verification/bench/bridge-bench.tcl ?repeat? ?csv?
#
# Each case runs `repeat` times (default 3) under the Takatori record (verification/data)
# and under the built-in near-fault pulse; the table gives the median wall time of the repeats,
# measured one after another in this one process. The error that goes with these times is the
# speed study's (verification/bridge/tools/results/speed.md): the default settings against a
# run with a 20 times smaller step.
set repeat [expr {$argc > 0 ? [lindex $argv 0] : 3}]
set csvName [expr {$argc > 1 ? [lindex $argv 1] : "bridge-bench.csv"}]
set ::bridgeLibraryOnly 1
source [file join [file dirname [info script]] .. bridge bridge.tcl]

proc median {values} {
  set s [lsort -real $values]
  set n [llength $s]
  return [expr {$n % 2 ? [lindex $s [expr {$n / 2}]] : 0.5 * ([lindex $s [expr {$n / 2 - 1}]] + [lindex $s [expr {$n / 2}]])}]
}

set motions [expr {[file exists $recordFile] ? {record pulse} : {pulse}}]
set csv [open $csvName w]
puts $csv "motion,case,equations,steps,contact_steps,iterations,factorizations,failed,median_wall_s,min_wall_s,max_wall_s"
puts [format "%-7s %-15s %5s %6s %8s %6s %7s %6s %9s %9s" motion case eqs steps contact iter fact failed "median s" "range s"]
foreach motion $motions {
  foreach case {nopound pound countermeasure} {
    set walls {}
    for {set k 0} {$k < $repeat} {incr k} {
      set r [runCase $case 1.0 $defaultDt $defaultIntegrator $defaultTol $motion]
      lappend walls [dict get $r wall]
    }
    set st [dict get $r stats]
    set m [median $walls]
    set lo [tcl::mathfunc::min {*}$walls]; set hi [tcl::mathfunc::max {*}$walls]
    puts $csv [join [list $motion $case [dict get $st equations] [dict get $st steps] [dict get $r contactSubsteps] \
        [dict get $st iterations] [dict get $st factorizations] [dict get $st failedSteps] \
        [format %.3f $m] [format %.3f $lo] [format %.3f $hi]] ,]
    puts [format "%-7s %-15s %5d %6d %8d %6d %7d %6d %9.2f %4.2f-%.2f" $motion $case [dict get $st equations] \
        [dict get $st steps] [dict get $r contactSubsteps] [dict get $st iterations] [dict get $st factorizations] \
        [dict get $st failedSteps] $m $lo $hi]
  }
}
close $csv
