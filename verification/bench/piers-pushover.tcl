# SPDX-License-Identifier: MIT
# Benchmark of a 3D fiber pier: pushover and cyclic time history, wall time and Newton
# iterations against the error from a reference run with a ten times smaller step.
# Run: dabs verification/bench/piers-pushover.tcl ?csv?   (default piers-pushover.csv)
# Model: circular RC pier D = 2 m, L = 10 m (the materials and section of
# verification/opensees/pier-pushover.tcl), one forceBeamColumn with 5 Lobatto points,
# PDelta, axial load 0.1 f'c Ag, 800 t deck mass at the top for the time history.
#  1. pushover in X by DisplacementControl to 0.4 m (past the peak), steps du and du/10;
#     error: largest |V - V_ref| at the coarse points, relative to the peak shear;
#  2. sine ground acceleration in X (period 0.8 s, 0.35 g, 6 s), Newmark average acceleration,
#     2 % mass-proportional damping, steps dt and dt/10; error: largest |u - u_ref| of the tip
#     displacement at the coarse times, relative to the peak tip displacement.
set csv [expr {$argc > 0 ? [lindex $argv 0] : "piers-pushover.csv"}]
set PI [expr {acos(-1.0)}]

source [file join [file dirname [info script]] opensees common.tcl]

# The pier of verification/opensees/pier-pushover.tcl with the deck mass, under its axial load.
proc buildPier {} {
  circularPier {
    D 2.0 cover 0.075 height 10.0
    core {-40000.0 -0.0025 -8000.0 -0.02 0.1 3000.0 1.5e6}
    coverConcrete {-30000.0 -0.002 -5000.0 -0.005 0.1 2500.0 1.2e6}
    steel {400000.0 2.0e8 0.01 18.0 0.925 0.15}
    G 1.04e7 sectors 16 bars 40 barArea 0.000804 lastBarAngle 351.0
    axialRatio 0.1 gravitySteps 1
  }
  mass 2 800.0 800.0 800.0 0.0 0.0 0.0
  wipeAnalysis
}

proc iterations {} {
  set s [analysisStatistics]
  return [dict get $s iterations]
}

# Pushover with step du to uMax; returns {wall_s iterations failed {u V ...}}.
proc pushover {du uMax} {
  buildPier
  timeSeries Linear 2
  pattern Plain 2 2 { load 2 1.0 0 0 0 0 0 }
  constraints Plain; numberer Plain; system BandGeneral
  test NormDispIncr 1.0e-8 50; algorithm Newton
  integrator DisplacementControl 2 1 $du
  analysis Static
  set n [expr {int(round($uMax / $du))}]
  set it0 [iterations]
  set t0 [clock microseconds]
  set out {}
  set failed 0
  for {set i 0} {$i < $n} {incr i} {
    if {[analyze 1] != 0} { incr failed; break }
    reactions
    lappend out [nodeDisp 2 1] [expr {-[nodeReaction 1 1]}]
  }
  set wall [expr {([clock microseconds] - $t0) * 1e-6}]
  return [list $wall [expr {[iterations] - $it0}] $failed $out]
}

# Sine ground motion with step dt for tEnd seconds; returns {wall_s iterations failed {t u ...}}.
proc timeHistory {dt tEnd} {
  global PI
  buildPier
  timeSeries Trig 3 0.0 $tEnd 0.8 -factor [expr {0.35 * 9.81}]
  pattern UniformExcitation 3 1 -accel 3
  rayleigh [expr {2.0 * 0.02 * 2.0 * $PI / 0.75}] 0.0 0.0 0.0
  constraints Plain; numberer Plain; system BandGeneral
  test NormDispIncr 1.0e-8 50; algorithm Newton
  integrator Newmark 0.5 0.25
  analysis Transient
  set n [expr {int(round($tEnd / $dt))}]
  set it0 [iterations]
  set t0 [clock microseconds]
  set out {}
  set failed 0
  for {set i 0} {$i < $n} {incr i} {
    if {[analyze 1 $dt] != 0} { incr failed; break }
    lappend out [expr {($i + 1) * $dt}] [nodeDisp 2 1]
  }
  set wall [expr {([clock microseconds] - $t0) * 1e-6}]
  return [list $wall [expr {[iterations] - $it0}] $failed $out]
}

# Largest difference of the coarse values against the reference sampled every `ratio` points,
# relative to the largest reference magnitude.
proc relError {coarse ref ratio} {
  set peak 0.0
  foreach {x y} $ref { set peak [expr {max($peak, abs($y))}] }
  set worst 0.0
  set i 0
  foreach {x y} $coarse {
    set j [expr {($i + 1) * $ratio - 1}]
    if {2 * $j + 1 >= [llength $ref]} break
    set yr [lindex $ref [expr {2 * $j + 1}]]
    set worst [expr {max($worst, abs($y - $yr))}]
    incr i
  }
  return [expr {$worst / $peak}]
}

set rows {}
puts [format "%-12s %10s %8s %10s %11s %7s %12s" case step steps wall_s iterations failed rel_error]
lassign [pushover 0.0005 0.4] refWall refIt refFail refOut
lappend rows [list pushover 0.0005 [expr {[llength $refOut] / 2}] $refWall $refIt $refFail 0.0]
foreach du {0.02 0.01 0.005} {
  lassign [pushover $du 0.4] wall it failed out
  set ratio [expr {int(round($du / 0.0005))}]
  lappend rows [list pushover $du [expr {[llength $out] / 2}] $wall $it $failed [relError $out $refOut $ratio]]
}
set ref10 {}
foreach dt {0.02 0.01} {
  lassign [timeHistory [expr {$dt / 10.0}] 6.0] rWall rIt rFail rOut
  lappend rows [list timeHistory [expr {$dt / 10.0}] [expr {[llength $rOut] / 2}] $rWall $rIt $rFail 0.0]
  lassign [timeHistory $dt 6.0] wall it failed out
  lappend rows [list timeHistory $dt [expr {[llength $out] / 2}] $wall $it $failed [relError $out $rOut 10]]
}
set f [open $csv w]
puts $f "case,step,steps,wall_s,iterations,failed_steps,rel_error_vs_step_over_10"
foreach r $rows {
  lassign $r c s n w i fl e
  puts [format "%-12s %10g %8d %10.3f %11d %7d %12.3e" $c $s $n $w $i $fl $e]
  puts $f [join $r ,]
}
close $f
puts "wrote $csv"
