# SPDX-License-Identifier: MIT
# Multiple-support excitation with the same motion at every support equals uniform excitation.
#
# Source: Chopra, Dynamics of Structures (4th ed.), §9.7 (multiple-support excitation): with the
# total displacements u^t = u^s + u, where u^s = 1 u_g is the quasi-static (rigid-body) part when
# all supports move alike, the equation of the relative motion is the uniform-excitation one,
# M u'' + C u' + K u = -M 1 u_g''   (Chopra eq. 9.7.7 reduces to eq. 9.4.x).
# So: total displacement (MultipleSupport) = relative displacement (UniformExcitation) + u_g.
# Conditions: lumped (diagonal) mass and stiffness-proportional damping (C 1 = 0 for a
# rigid-body motion; mass-proportional damping would act on the total velocity in one model and
# on the relative velocity in the other). With Newmark's average acceleration (gamma 1/2, beta 1/4)
# the trapezoid double integration of u_g'' is exactly Newmark's own kinematics, so the two
# discrete solutions agree to round-off: tolerance 1e-6 of the peak relative displacement.
# u_g is also integrated independently here (trapezoid rule in Tcl) and compared with the
# support's displacement.
source [file join [file dirname [info script]] .. lib check.tcl]

set TOL_EQUIVALENCE 1e-6
set TOL_GROUND 1e-9
set g 386.4
set dt 0.02
set nSteps 500   ;# the first 10 s of the record

# read the El Centro record (values after the NPTS line), in g
set values {}
set f [open [recordPath elCentro.at2]]
set inData 0
while {[gets $f line] >= 0} {
  if {$inData} { foreach v $line { if {[string is double -strict $v]} { lappend values $v } } }
  if {[string match *NPTS* $line]} { set inData 1 }
}
close $f
# start the ground at rest with zero acceleration: prepend a zero sample; keep a few samples more
# than the analysis uses, so that no step lands on the series' last point (a Path series, like
# OpenSees', is 0 from its last point on, and n*dt in floating point may fall either side of it)
set accel [linsert [lrange $values 0 [expr {$nSteps + 4}]] 0 0.0]

# independent trapezoid integration: ground displacement at step i (t = i dt)
set ug {0.0}; set vg 0.0; set dg 0.0
for {set i 1} {$i <= $nSteps} {incr i} {
  set a0 [expr {$g * [lindex $accel [expr {$i - 1}]]}]
  set a1 [expr {$g * [lindex $accel $i]}]
  set vn [expr {$vg + 0.5 * $dt * ($a0 + $a1)}]
  set dg [expr {$dg + 0.5 * $dt * ($vg + $vn)}]
  set vg $vn
  lappend ug $dg
}

set h 144.0; set L 240.0; set E 29000.0; set A 20.0; set I 1000.0
proc frame {supportFix} {
  wipe
  model basic -ndm 2 -ndf 3
  node 1 0.0 0.0
  node 2 $::L 0.0
  node 3 0.0 $::h -mass 1.0 1.0 0.0
  node 4 $::L $::h -mass 1.0 1.0 0.0
  node 5 0.0 [expr {$::h / 2.0}] -mass 0.2 0.2 0.0
  fix 1 {*}$supportFix
  fix 2 {*}$supportFix
  geomTransf Linear 1
  element elasticBeamColumn 1 1 5 $::A $::E $::I 1
  element elasticBeamColumn 2 5 3 $::A $::E $::I 1
  element elasticBeamColumn 3 2 4 $::A $::E $::I 1
  element elasticBeamColumn 4 3 4 $::A $::E [expr {2.0 * $::I}] 1
  timeSeries Path 1 -dt $::dt -values $::accel -factor $::g
}
proc analysisSetup {} {
  rayleigh 0.0 0.01 0.0 0.0
  constraints Transformation
  numberer RCM
  system BandGeneral
  test NormDispIncr 1e-12 10
  algorithm Linear
  integrator Newmark 0.5 0.25
  analysis Transient
}

# uniform excitation: relative displacements
frame {1 1 1}
pattern UniformExcitation 1 1 -accel 1
analysisSetup
set rel {}
for {set i 1} {$i <= $nSteps} {incr i} {
  if {[analyze 1 $dt] != 0} { error "uniform: analyze failed at step $i" }
  lappend rel [list [nodeDisp 3 1] [nodeDisp 4 1] [nodeDisp 5 1]]
}

# multiple support: the same motion imposed at both supports (dof 1 free there)
frame {0 1 1}
pattern MultipleSupport 2 {
  groundMotion 1 Plain -accel 1
  imposedMotion 1 1 1
  imposedMotion 2 1 1
}
analysisSetup
set worst 0.0; set peak 0.0; set worstGround 0.0; set peakGround 0.0
for {set i 1} {$i <= $nSteps} {incr i} {
  if {[analyze 1 $dt] != 0} { error "multiple support: analyze failed at step $i" }
  set u [lindex $ug $i]
  set peakGround [expr {max($peakGround, abs($u))}]
  set worstGround [expr {max($worstGround, abs([nodeDisp 1 1] - $u), abs([nodeDisp 2 1] - $u))}]
  foreach node {3 4 5} r [lindex $rel [expr {$i - 1}]] {
    set peak [expr {max($peak, abs($r))}]
    set worst [expr {max($worst, abs([nodeDisp $node 1] - ($r + $u)))}]
  }
}
checkTrue "the frame moves (peak relative displacement $peak in > 0.1 in)" [expr {$peak > 0.1}]
checkAbs "Chopra §9.7: support displacement = trapezoid double integral of u_g'' (/peak u_g)" \
  [expr {$worstGround / $peakGround}] 0.0 $TOL_GROUND
checkAbs "Chopra §9.7: total (MultipleSupport) - relative (Uniform) - u_g, max/peak rel" \
  [expr {$worst / $peak}] 0.0 $TOL_EQUIVALENCE
wipe
finish
