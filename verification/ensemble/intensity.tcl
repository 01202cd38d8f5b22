# SPDX-License-Identifier: MIT
# Intensity measures of a ground motion computed with dabs itself, from the same timeSeries command
# the analysis uses (a record's Path series or the built-in NearFaultPulse):
#   PGV   peak ground velocity: the peak relative velocity of an undamped oscillator of 1000 s
#         period, which over a record's length moves as minus the ground (its restoring force is
#         (2 pi / 1000)^2 = 4e-5 of its displacement); Newmark's average acceleration integrates
#         the acceleration by the trapezoid rule
#   Sa(T) pseudo-spectral acceleration (2 pi / T)^2 D of an oscillator of period T and damping
#         ratio zeta (Chopra, Dynamics of Structures, section 6.6)
#
#   intensity::measures seriesScript T zeta duration dt  -> dict pgv sa (units of the series)
#   intensity::recordHeader file                         -> dict npts dt (PEER .AT2 headers)
# seriesScript defines `timeSeries ... 1 ...` in acceleration units. It wipes the model.

namespace eval intensity {}

proc intensity::recordHeader {file} {
  set fh [open $file]
  set head [read $fh 2000]
  close $fh
  if {![regexp -nocase {NPTS\s*=\s*([0-9]+)[ ,]+DT\s*=\s*([0-9.Ee+-]+)} $head -> npts dt]} {
    error "intensity::recordHeader: no NPTS= and DT= in the header of $file"
  }
  return [dict create npts $npts dt [expr {double($dt)}]]
}

proc intensity::measures {seriesScript T zeta duration dt} {
  set pi [expr {acos(-1.0)}]
  set w [expr {2.0 * $pi / $T}]
  set wFree [expr {2.0 * $pi / 1000.0}]
  wipe
  model basic -ndm 1 -ndf 1
  node 1 0.0; node 2 0.0 -mass 1.0
  node 3 0.0; node 4 0.0 -mass 1.0
  fix 1 1; fix 3 1
  uniaxialMaterial Elastic 1 [expr {$w * $w}] [expr {2.0 * $zeta * $w}]
  uniaxialMaterial Elastic 2 [expr {$wFree * $wFree}]
  element zeroLength 1 1 2 -mat 1 -dir 1
  element zeroLength 2 3 4 -mat 2 -dir 1
  uplevel #0 $seriesScript
  pattern UniformExcitation 1 1 -accel 1
  constraints Plain; numberer Plain; system BandGeneral
  test NormDispIncr 1e-12 10; algorithm Linear
  integrator Newmark 0.5 0.25
  analysis Transient
  set dMax 0.0; set vMax 0.0
  set n [expr {int(round($duration / $dt))}]
  for {set i 0} {$i < $n} {incr i} {
    if {[analyze 1 $dt] != 0} { error "intensity::measures: analysis failed at step $i" }
    set d [expr {abs([nodeDisp 2 1])}]
    set v [expr {abs([nodeVel 4 1])}]
    if {$d > $dMax} { set dMax $d }
    if {$v > $vMax} { set vMax $v }
  }
  wipe
  return [dict create pgv $vMax sa [expr {$w * $w * $dMax}] sd $dMax]
}
