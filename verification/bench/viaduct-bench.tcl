# SPDX-License-Identifier: MIT
# The case study's pound case as a viaduct of nSpans spans (verification/bridge/bridge.tcl) under
# the Takatori record: one run, its counts and the quantities the study reports, for the
# viaduct benchmark (results/viaduct.md).
#
#   dabs verification/bench/viaduct-bench.tcl nSpans ?dt? ?tol? ?contactDt? ?lookAhead? ?duration? ?out?
#
# Prints one line: spans, equations, steps, contact steps, iterations, factorisations, element
# updates, wall and CPU seconds of the steps, and per span-step costs. Writes `out` (default
# viaduct-<nSpans>-<dt>-<contactDt>-<lookAhead>.txt) with the run's line and its quantities (a Tcl
# dict): every joint's peak and residual longitudinal and transverse gaps and every bearing's
# peak shear strain, which viaduct-compare.tcl compares with a reference run of the same size.
# The default dt is the viaducts' (bridge.tcl viaductDt, 0.0025 s) at every size, so that the
# sizes are compared at the same settings.
set ::bridgeLibraryOnly 1
source [file join [file dirname [info script]] .. bridge bridge.tcl]
set nSpans    [lindex $argv 0]
set dt        [expr {$argc > 1 ? [lindex $argv 1] : $viaductDt}]
set tol       [expr {$argc > 2 ? [lindex $argv 2] : $defaultTol}]
set contactDt [expr {$argc > 3 ? [lindex $argv 3] : $contactDt}]
set contactLookahead [expr {$argc > 4 ? [lindex $argv 4] : $contactLookahead}]
set duration  [expr {$argc > 5 ? [lindex $argv 5] : $duration}]
set out       [expr {$argc > 6 ? [lindex $argv 6] : "viaduct-$nSpans-$dt-$contactDt-$contactLookahead.txt"}]

source [file join [file dirname [info script]] cpu-time.tcl]
set c0 [cpuSeconds]
set r [runCase pound 1.0 $dt Newmark $tol record]
set cpu [expr {[cpuSeconds] - $c0}]
set st [dict get $r stats]
set steps [dict get $st steps]
set q [dict create]
for {set j 1} {$j < $nSpans} {incr j} {
  foreach d {x y} {
    dict set q peak_gap$j$d [expr {abs([dict get $r peak gap$j$d])}]
    dict set q residual_gap$j$d [dict get $r last gap$j$d]
  }
}
foreach bt [bearingTags] { dict set q strain$bt [dict get $r peak strain$bt] }
set line [format "spans %d equations %d dt %g contactDt %g lookAhead %g steps %d contactSteps %d iterations %d factorizations %d elementUpdates %d wall %.2f cpu %.2f completed %d us_per_span_step %.1f iterations_per_step %.3f" \
    $nSpans [dict get $st equations] $dt $contactDt $contactLookahead $steps [dict get $r contactSubsteps] \
    [dict get $st iterations] [dict get $st factorizations] [dict get $st elementUpdates] [dict get $r wallSteps] $cpu \
    [dict get $r completed] [expr {1e6 * $cpu / ($nSpans * $steps)}] [expr {double([dict get $st iterations]) / $steps}]]
puts $line
set f [open $out w]
puts $f $line
puts $f $q
close $f
