# SPDX-License-Identifier: MIT
# Shared by the benchmark models (plain Tcl, so dabs and OpenSees run the same code).
#
# timedAnalyze label args: runs `analyze args`, prints "label status=.. analyze_s=.." (the line
# compare.sh reads) and, in dabs, the work counts of analysisStatistics.
proc timedAnalyze {label args} {
  # Microseconds: the pushover's analysis takes about 10 ms, which whole milliseconds would
  # round by up to a tenth.
  set t0 [clock microseconds]
  set ok [analyze {*}$args]
  set wall [expr {([clock microseconds] - $t0)/1.0e6}]
  puts "$label status=$ok analyze_s=$wall"
  if {[info commands analysisStatistics] ne ""} { puts "counts [analysisStatistics]" }
  return $ok
}

# Reads a PEER NGA .AT2 record (header lines, then `NPTS= n, DT= dt SEC`, then values in g, up
# to a trailer such as `*** End data ***` if there is one) and
# writes its values one a line to a plain file that `timeSeries Path -filePath` reads in any
# OpenSees-compatible program. Plain Tcl, so dabs and OpenSees run the same code.
#
#   set dt [writePlainRecord in.AT2 out.txt]   ;# returns the record's time step

set ::benchRecordDir [file dirname [file normalize [info script]]]

proc findRecord {name} {
  set f [file normalize [file join $::benchRecordDir .. .. data $name]]
  if {![file exists $f]} { error "record $name not found in verification/data" }
  return $f
}

proc writePlainRecord {at2 out} {
  set in [open $at2 r]
  set dt ""
  set values {}
  while {[gets $in line] >= 0} {
    if {$dt eq ""} {
      if {[regexp -nocase {NPTS\s*=\s*([0-9]+)\s*,\s*DT\s*=\s*([0-9.Ee+-]+)} $line -> npts dt]} { continue }
      continue
    }
    foreach v $line {
      if {![string is double -strict $v]} { break }
      lappend values $v
    }
  }
  close $in
  if {$dt eq ""} { error "$at2: no `NPTS= .., DT= ..` header line" }
  set f [open $out w]
  foreach v $values { puts $f $v }
  close $f
  return [expr {double($dt)}]
}

# The benchmarks' circular RC pier: node 1 fixed at the origin, node 2 at the top, one
# forceBeamColumn with 5 Lobatto points of a fiber section (Concrete02 core and cover rings,
# Steel02 bars on one circle) and a PDelta transformation, under an axial load applied in
# `gravitySteps` LoadControl steps and then held (loadConst -time 0). The static analysis it
# used stays defined. `p` is a dict of:
#   D cover height          diameter, cover to the core's edge, pier height (m)
#   core coverConcrete steel the material arguments after the tag (Concrete02, Concrete02, Steel02)
#   G sectors bars barArea lastBarAngle   shear modulus (GJ = G pi D^4 / 32), fiber sectors of
#                           the rings (core: 8 rings, cover: 2), bars, their area, the angle of
#                           the last bar (degrees)
#   axialRatio gravitySteps P = axialRatio x 30 MPa x Ag, in that many steps
# Plain Tcl, so dabs and OpenSees build the same pier.
proc circularPier {p} {
  dict with p {}
  set PI [expr {acos(-1.0)}]
  wipe
  model basic -ndm 3 -ndf 6
  uniaxialMaterial Concrete02 1 {*}$core
  uniaxialMaterial Concrete02 2 {*}$coverConcrete
  uniaxialMaterial Steel02 3 {*}$steel
  set rCore [expr {$D/2.0 - $cover}]
  section Fiber 1 -GJ [expr {$G*$PI*pow($D,4)/32.0}] {
    patch circ 1 $sectors 8 0.0 0.0 0.0 $rCore 0.0 360.0
    patch circ 2 $sectors 2 0.0 0.0 $rCore [expr {$D/2.0}] 0.0 360.0
    layer circ 3 $bars $barArea 0.0 0.0 [expr {$rCore - 0.02}] 0.0 $lastBarAngle
  }
  beamIntegration Lobatto 1 1 5
  geomTransf PDelta 1 1.0 0.0 0.0
  node 1 0 0 0
  node 2 0 0 $height
  fix 1 1 1 1 1 1 1
  element forceBeamColumn 1 1 2 1 1
  set P [expr {$axialRatio*30000.0*$PI*$D*$D/4.0}]
  timeSeries Constant 1
  pattern Plain 1 1 [list load 2 0 0 [expr {-$P}] 0 0 0]
  constraints Plain; numberer Plain; system BandGeneral
  test NormDispIncr 1.0e-8 50; algorithm Newton
  integrator LoadControl [expr {1.0/$gravitySteps}]; analysis Static
  analyze $gravitySteps
  loadConst -time 0.0
}
