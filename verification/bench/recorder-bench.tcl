# SPDX-License-Identifier: MIT
# Cost of recorder output. Run: dabs verification/bench/recorder-bench.tcl ?repeat? ?csv?
#  1. A small transient script (a 20-storey shear building, 20,000 Newmark steps, three recorders)
#     run as one `analyze 20000`, as a loop of 20,000 `analyze 1`, and without recorders. Every
#     committed step's rows are handed to the operating system when the step commits, in both
#     forms; the loop must cost at most 1.1 times the single call.
#  2. The bridge case study (verification/bridge/bridge.tcl, case nopound under the fitted pulse,
#     2,000 steps of `analyze 1` from Tcl) without recorders, with recorders of the quantities the
#     study reports (must add at most 5 %), and with every node's six displacements as well.
# The machine is shared, so besides wall time the processor time of this process (user + system,
# from /proc/self/stat, 10 ms resolution) is measured; the targets are checked on the smallest
# processor time of `repeat` runs (default 5) made one after another in this process, and the
# median wall time is printed beside it.
set repeat [expr {$argc > 0 ? [lindex $argv 0] : 5}]
set csvName [expr {$argc > 1 ? [lindex $argv 1] : "recorder-bench.csv"}]
set tmp [file join [pwd] recorder-bench-out]
file mkdir $tmp

# Processor time (user + system) of this process in seconds, Linux only.
source [file join [file dirname [info script]] cpu-time.tcl]

proc median {values} {
  set s [lsort -real $values]
  set n [llength $s]
  return [expr {$n % 2 ? [lindex $s [expr {$n / 2}]] : 0.5 * ([lindex $s [expr {$n / 2 - 1}]] + [lindex $s [expr {$n / 2}]])}]
}

# --- 1. shear building ---
proc building {withRecorders} {
  global tmp
  wipe
  model basic -ndm 1 -ndf 1
  node 0 0.0
  fix 0 1
  uniaxialMaterial Steel01 1 400.0 2.0e4 0.05
  for {set i 1} {$i <= 20} {incr i} {
    node $i 0.0 -mass 10.0
    element zeroLength $i [expr {$i - 1}] $i -mat 1 -dir 1
  }
  timeSeries Trig 1 0.0 100.0 0.8 -factor 6.0
  pattern UniformExcitation 1 1 -accel 1
  if {$withRecorders} {
    recorder Node -file [file join $tmp disp.out] -time -nodeRange 1 20 -dof 1 disp
    recorder Element -file [file join $tmp force.out] -time -eleRange 1 20 force
    recorder EnvelopeNode -file [file join $tmp env.out] -nodeRange 1 20 -dof 1 disp
  }
  rayleigh 0.2 0.0 0.0 0.002
  constraints Plain
  numberer Plain
  system BandGeneral
  test NormDispIncr 1e-10 20
  algorithm Newton
  integrator Newmark 0.5 0.25
  analysis Transient
}
proc timeBuilding {form withRecorders} {
  building $withRecorders
  set t0 [clock microseconds]
  set c0 [cpuSeconds]
  if {$form eq "one"} {
    if {[analyze $::steps 0.001] != 0} { error "analyze failed" }
  } else {
    for {set k 0} {$k < $::steps} {incr k} { if {[analyze 1 0.001] != 0} { error "analyze failed" } }
  }
  set c [expr {[cpuSeconds] - $c0}]
  set t [expr {([clock microseconds] - $t0) * 1e-6}]
  wipe
  return [list $t $c]
}

set steps 20000
set csv [open $csvName w]
puts $csv "case,min_cpu_s,median_cpu_s,median_wall_s,min_wall_s,max_wall_s"
set results [dict create]
proc report {name walls cpus} {
  global results csv
  dict set results $name [tcl::mathfunc::min {*}$cpus]
  puts [format "%-36s cpu min %.3f s median %.3f s | wall median %.3f s (range %.3f-%.3f)" $name \
      [tcl::mathfunc::min {*}$cpus] [median $cpus] [median $walls] [tcl::mathfunc::min {*}$walls] [tcl::mathfunc::max {*}$walls]]
  puts $csv [join [list $name [format %.3f [tcl::mathfunc::min {*}$cpus]] [format %.3f [median $cpus]] \
      [format %.3f [median $walls]] [format %.3f [tcl::mathfunc::min {*}$walls]] [format %.3f [tcl::mathfunc::max {*}$walls]]] ,]
}
foreach {name form rec} {one-analyze one 1 loop-analyze-1 loop 1 one-analyze-no-recorders one 0 loop-no-recorders loop 0} {
  set walls {}; set cpus {}
  for {set rep 0} {$rep < $repeat} {incr rep} {
    lassign [timeBuilding $form $rec] w c
    lappend walls $w; lappend cpus $c
  }
  report building-$name $walls $cpus
}
set ratio [expr {[dict get $results building-loop-analyze-1] / [dict get $results building-one-analyze]}]
puts [format "loop of analyze 1 / one analyze $steps (processor time): %.3f (target <= 1.1)" $ratio]

# --- 2. bridge ---
set ::bridgeLibraryOnly 1
source [file join [file dirname [info script]] .. bridge bridge.tcl]
# The quantities the case study reports: girder ends and mid-spans (6 dofs each), the bearings of
# the four girder ends at the joints (their forces and deformations), the pounding elements'
# contact forces.
proc studyRecorders {} {
  global tmp
  if {[info exists ::recordersAdded]} { return }
  set ::recordersAdded 1
  set nodes [concat $::girderEndNodes [dict values $::girderMid]]
  recorder Node -file [file join $tmp bridge-disp.out] -time -node {*}$nodes -dof 1 2 3 4 5 6 disp
  set bearings [concat {*}[lmap bt {2011 2012 3011 3012} { endBearings $bt }]]
  recorder Element -file [file join $tmp bridge-bearings.out] -time -ele {*}$bearings force
  recorder Element -file [file join $tmp bridge-bearing-def.out] -time -ele {*}$bearings deformation
  set contacts [concat {*}$::poundingEles]
  if {[llength $contacts]} {
    recorder Element -file [file join $tmp bridge-pounding.out] -time -ele {*}$contacts contactForce
  }
}
# Those and every node's six displacements (607 numbers per step).
proc everyNodeRecorders {} {
  global tmp
  if {[info exists ::recordersAdded]} { return }
  studyRecorders
  recorder Node -file [file join $tmp bridge-all.out] -time -nodeRange 1 2147483647 -dof 1 2 3 4 5 6 disp
}
proc noRecorders {} {}
foreach {name hook} {bridge-no-recorders noRecorders bridge-study-recorders studyRecorders bridge-every-node-recorders everyNodeRecorders} {
  set walls {}; set cpus {}
  for {set rep 0} {$rep < $repeat} {incr rep} {
    unset -nocomplain ::recordersAdded
    set c0 [cpuSeconds]
    set r [runCase nopound 1.0 $defaultDt $defaultIntegrator $defaultTol pulse "" $hook]
    lappend cpus [expr {[cpuSeconds] - $c0}]
    lappend walls [dict get $r wall]
    wipe
  }
  report $name $walls $cpus
}
set added [expr {[dict get $results bridge-study-recorders] / [dict get $results bridge-no-recorders] - 1.0}]
set addedAll [expr {[dict get $results bridge-every-node-recorders] / [dict get $results bridge-no-recorders] - 1.0}]
puts [format "the study's recorders add %.1f %% processor time to the bridge run (target <= 5 %%)" [expr {100.0 * $added}]]
puts [format "with every node's displacements as well: %.1f %%" [expr {100.0 * $addedAll}]]
puts $csv "ratio_loop_to_one,[format %.3f $ratio]"
puts $csv "bridge_study_recorders_overhead_percent,[format %.1f [expr {100.0 * $added}]]"
puts $csv "bridge_every_node_recorders_overhead_percent,[format %.1f [expr {100.0 * $addedAll}]]"
close $csv
file delete -force $tmp
