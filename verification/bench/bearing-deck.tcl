# SPDX-License-Identifier: MIT
# Benchmark of the Yoshida bearing (speed): an isolated-deck oscillator under the
# Takatori record, wall time against the error from a reference run with a ten times smaller step.
# Run: dabs verification/bench/bearing-deck.tcl ?csv? ?nBearings?
#      (defaults bearing-deck.csv and 4; nBearings 1 or 4)
#
# Model (kN, m, t, s): a rigid deck node carrying 250 t per bearing on nBearings yoshidaBearing
# elements in parallel (each between its own fixed ground node and the deck node, coincident
# nodes, axis global Z). Each bearing: HDR X0.6, A = 0.64 m^2, Tr = 0.2 m, with the fitted set (a)
# of verification/bearing/fitted-parameters.md scaled to the bearing (Y0 * A, U0 * Tr), no Maxwell
# part. Equivalent period at 150 % strain 2.28 s (Geq 0.595 MPa there, fitted-parameters.md).
# The deck moves in X and Y only (vertical and rotations fixed); since every bearing sees the
# same deformation, the response does not depend on nBearings, only the cost does. No Rayleigh
# damping (the bearings' hysteresis is the damping).
# Ground motion: RSN1120 Kobe Takatori 90 (PEER NGA, 4096 points at 0.01 s, in g), applied at
# 30 degrees to global X (components cos and sin of the same record) so that both shear
# directions work at once. Newmark average acceleration, Newton, NormDispIncr 1e-9.
#
# For dt = 0.02, 0.01, 0.005, 0.0025 (and a reference at dt/10 for each) the whole 40.96 s record
# is run, one `analyze 1 $dt` per step with nodeDisp queries (their cost is in the wall time).
# Errors, relative to the reference run's value:
#   peak_disp   largest |u| of the deck in the horizontal plane
#   peak_strain the bearing's maxShearStrain at the end
#   history     largest |u_x - u_x,ref| at the coarse times (reference sampled at every 10th step),
#               relative to the reference's peak |u_x|
set csv [expr {$argc > 0 ? [lindex $argv 0] : "bearing-deck.csv"}]
set nBearings [expr {$argc > 1 ? [lindex $argv 1] : 4}]
set record [file join [file dirname [info script]] .. data RSN1120_KOBE_TAK090.AT2]
set PI [expr {acos(-1.0)}]
set duration 40.96

proc buildDeck {} {
  global nBearings record PI
  wipe
  model basic -ndm 3 -ndf 6
  set A 0.64; set Tr 0.2
  set M [expr {250.0 * $nBearings}]
  node 100 0.0 0.0 0.0 -mass $M $M $M 0.0 0.0 0.0
  fix 100 0 0 1 1 1 1
  # HDR X0.6 fitted set (a), per unit area and rubber thickness (MPa, strain) -> kN, m.
  biaxialMaterial Yoshida 1 [expr {0.435794e3 * $A}] [expr {0.0683367 * $Tr}] 0.115167 0.831926 0.698464 0.0393774 0.000947439
  for {set b 1} {$b <= $nBearings} {incr b} {
    node $b 0.0 0.0 0.0
    fix $b 1 1 1 1 1 1
    element yoshidaBearing $b $b 100 1 -Tr $Tr -Kv 2.0e6 -Kt 500.0 -Kr 8000.0
  }
  set angle [expr {$PI / 6.0}]
  timeSeries Path 1 -filePath $record -factor [expr {9.81 * cos($angle)}]
  timeSeries Path 2 -filePath $record -factor [expr {9.81 * sin($angle)}]
  pattern UniformExcitation 1 1 -accel 1
  pattern UniformExcitation 2 2 -accel 2
  constraints Plain; numberer Plain; system BandGeneral
  test NormDispIncr 1.0e-9 30; algorithm Newton
  integrator Newmark 0.5 0.25
  analysis Transient
}

proc iterations {} { return [dict get [analysisStatistics] iterations] }

# Whole record with step dt; returns {wall_s iterations failed peakDisp peakStrain {ux ...}}.
proc run {dt} {
  global duration
  buildDeck
  set n [expr {int(round($duration / $dt))}]
  set it0 [iterations]
  set ux {}
  set peak 0.0
  set failed 0
  set t0 [clock microseconds]
  for {set i 0} {$i < $n} {incr i} {
    if {[analyze 1 $dt] != 0} { incr failed; break }
    set x [nodeDisp 100 1]
    set y [nodeDisp 100 2]
    set peak [expr {max($peak, hypot($x, $y))}]
    lappend ux $x
  }
  set wall [expr {([clock microseconds] - $t0) * 1e-6}]
  set strain [lindex [eleResponse 1 maxShearStrain] 0]
  return [list $wall [expr {[iterations] - $it0}] $failed $peak $strain $ux]
}

proc historyError {coarse ref ratio} {
  set peak 0.0
  foreach y $ref { set peak [expr {max($peak, abs($y))}] }
  set worst 0.0
  set i 0
  foreach y $coarse {
    set j [expr {($i + 1) * $ratio - 1}]
    if {$j >= [llength $ref]} break
    set worst [expr {max($worst, abs($y - [lindex $ref $j]))}]
    incr i
  }
  return [expr {$worst / $peak}]
}

set header [format "%-9s %7s %9s %8s %6s %10s %11s %10s %11s %10s" \
  dt steps wall_s iters failed peak_disp err_disp peak_strain err_strain err_history]
puts "isolated deck on $nBearings yoshidaBearing(s), Takatori 90 at 30 deg, $duration s"
puts $header
set rows {}
foreach dt {0.02 0.01 0.005 0.0025} {
  set dtRef [expr {$dt / 10.0}]
  lassign [run $dtRef] rWall rIt rFail rPeak rStrain rUx
  lassign [run $dt] wall it failed peak strain ux
  set eDisp [expr {abs($peak - $rPeak) / $rPeak}]
  set eStrain [expr {abs($strain - $rStrain) / $rStrain}]
  set eHist [historyError $ux $rUx 10]
  foreach r [list [list $dtRef [llength $rUx] $rWall $rIt $rFail $rPeak 0.0 $rStrain 0.0 0.0 reference_for_$dt] \
                  [list $dt [llength $ux] $wall $it $failed $peak $eDisp $strain $eStrain $eHist run]] {
    lappend rows $r
    lassign $r d s w i f p ep st es eh
    puts [format "%-9g %7d %9.3f %8d %6d %10.5f %11.3e %10.5f %11.3e %10.3e" $d $s $w $i $f $p $ep $st $es $eh]
  }
}
set f [open $csv w]
puts $f "dt,steps,wall_s,iterations,failed_steps,peak_disp_m,rel_err_peak_disp,peak_shear_strain,rel_err_peak_strain,rel_err_history_ux,kind"
foreach r $rows { puts $f [join $r ,] }
close $f
puts "wrote $csv"
