# SPDX-License-Identifier: MIT
# Benchmark of the bridge case study: the cost of each case at the default settings, with
# equations, steps, iterations and factorisations, and the error that goes with it.
#
#   dabs verification/bench/bridge-bench.tcl ?repeat? ?csv?
#
# The three cases run under the Takatori record (verification/data) and under the fitted
# near-fault pulse, `repeat` times each (default 3), the cases alternating within each round so
# that a change of the machine's load hits them alike; the table gives the medians of the
# repeats' wall and CPU seconds (the CPU time of this process, less sensitive to other jobs on
# the machine) and the ratios of the pound and countermeasure cases to the no-pound case. The
# error of each case is its largest relative difference from a run of the same case at dt
# 0.0005 s and tol 1e-6 (not timed), over the quantities of the speed study
# (verification/bridge/tools/speed-error.tcl).
set repeat [expr {$argc > 0 ? [lindex $argv 0] : 3}]
set csvName [expr {$argc > 1 ? [lindex $argv 1] : "bridge-bench.csv"}]
set ::bridgeLibraryOnly 1
source [file join [file dirname [info script]] .. bridge bridge.tcl]
source [file join [file dirname [info script]] .. bridge tools speed-error.tcl]

proc median {values} {
  set s [lsort -real $values]
  set n [llength $s]
  return [expr {$n % 2 ? [lindex $s [expr {$n / 2}]] : 0.5 * ([lindex $s [expr {$n / 2 - 1}]] + [lindex $s [expr {$n / 2}]])}]
}
source [file join [file dirname [info script]] cpu-time.tcl]

set cases {nopound pound countermeasure}
set motions [expr {[file exists $recordFile] ? {record pulse} : {pulse}}]
set csv [open $csvName w]
puts $csv "motion,case,dt,equations,steps,contact_steps,iterations,factorizations,failed,median_wall_s,median_cpu_s,cpu_ratio_to_nopound,max_rel_error,worst_quantity"
puts [format "%-7s %-15s %5s %6s %8s %6s %7s %6s %8s %8s %7s %8s" motion case eqs steps contact iter fact failed "wall s" "cpu s" "ratio" "error"]
foreach motion $motions {
  set walls [dict create]; set cpus [dict create]; set last [dict create]
  for {set k 0} {$k < $repeat} {incr k} {
    foreach case $cases {
      set c0 [cpuSeconds]
      set r [runCase $case 1.0 $defaultDt $defaultIntegrator $defaultTol $motion]
      dict lappend cpus $case [expr {[cpuSeconds] - $c0}]
      dict lappend walls $case [dict get $r wall]
      dict set last $case $r
    }
  }
  foreach case $cases {
    set r [dict get $last $case]
    set ref [runCase $case 1.0 0.0005 Newmark 1e-6 $motion]
    lassign [errorOf [quantities $r] [quantities $ref]] err which
    set st [dict get $r stats]
    set cpu [median [dict get $cpus $case]]
    set ratio [expr {$cpu / [median [dict get $cpus nopound]]}]
    puts $csv [join [list $motion $case $defaultDt [dict get $st equations] [dict get $st steps] [dict get $r contactSubsteps] \
        [dict get $st iterations] [dict get $st factorizations] [dict get $st failedSteps] \
        [format %.3f [median [dict get $walls $case]]] [format %.3f $cpu] [format %.3f $ratio] [format %.4g $err] $which] ,]
    flush $csv
    puts [format "%-7s %-15s %5d %6d %8d %6d %7d %6d %8.2f %8.2f %7.2f %7.2f%% %s" $motion $case [dict get $st equations] \
        [dict get $st steps] [dict get $r contactSubsteps] [dict get $st iterations] [dict get $st factorizations] \
        [dict get $st failedSteps] [median [dict get $walls $case]] $cpu $ratio [expr {100 * $err}] $which]
  }
}
close $csv
