# SPDX-License-Identifier: MIT
# Pier pushover against OpenSees. Source: verification/opensees/pier-pushover.tcl (a
# circular RC pier, D = 2 m, L = 10 m, one forceBeamColumn with a Concrete02/Steel02 fiber section,
# PDelta, axial load 0.1 f'c Ag, displacement control in X) run unchanged; it writes
# pier-pushover.csv in the working directory, which is compared with the CSV OpenSees wrote
# (verification/opensees/pier-pushover.csv) at every reference point. OpenSees stops
# at 0.355 m (its Newton fails); the pushover is then continued here past that point, to a drift of
# 10 %, well past the peak, to check that the run completes through softening.
source [file join [file dirname [info script]] .. lib check.tcl]

# Relative tolerance on the base shear at each reference point. Both programs discretise the same
# section the same way and use the same material laws; what remains is round-off and the
# convergence tolerance (NormDispIncr 1e-8) of both Newton iterations.
set kShearTol 1e-4

set refFile [openseesReference pier-pushover.csv]
source [openseesReference pier-pushover.tcl]

proc readCsv {path} {
  set f [open $path r]
  gets $f header
  set rows {}
  while {[gets $f line] >= 0} {
    if {[string trim $line] eq ""} continue
    lappend rows [split $line ,]
  }
  close $f
  return $rows
}
set ref [readCsv $refFile]
set got [readCsv pier-pushover.csv]
checkTrue "dabs reaches every OpenSees point ([llength $ref] rows, dabs [llength $got])" \
    [expr {[llength $got] >= [llength $ref]}]
set worst 0.0
for {set i 0} {$i < min([llength $ref], [llength $got])} {incr i} {
  lassign [lindex $ref $i] uRef vRef
  lassign [lindex $got $i] u v
  checkAbs "tip displacement, point [expr {$i + 1}]" $u $uRef 1e-9
  check "base shear at u = $uRef m" $v $vRef $kShearTol
  set worst [expr {max($worst, abs($v - $vRef) / abs($vRef))}]
}
puts [format "largest relative base-shear difference from OpenSees: %.2e" $worst]

# Continue past OpenSees' last point to 10 % drift.
set uTarget 1.0
set du 0.005
set uNow [nodeDisp 2 1]
set vMax 0.0
foreach row $got { set vMax [expr {max($vMax, [lindex $row 1])}] }
set vNow [lindex $got end 1]
set completed 1
set subStepped 0
while {$uNow < $uTarget - 1e-12} {
  if {[analyze 1] != 0} {
    # Sub-step: ten steps of du/10 with more iterations allowed, then go on.
    incr subStepped
    integrator DisplacementControl 2 1 [expr {$du / 10.0}]
    test NormDispIncr 1.0e-8 200
    set bad 0
    for {set k 0} {$k < 10 && !$bad} {incr k} { set bad [expr {[analyze 1] != 0}] }
    integrator DisplacementControl 2 1 $du
    test NormDispIncr 1.0e-8 50
    if {$bad} { set completed 0; break }
  }
  reactions
  set uNow [nodeDisp 2 1]
  set vNow [expr {-[nodeReaction 1 1]}]
  set vMax [expr {max($vMax, $vNow)}]
}
puts [format "continued to u = %.4f m, base shear %.1f kN, peak %.1f kN (%d steps sub-stepped)" $uNow $vNow $vMax $subStepped]
checkTrue "pushover continues past 0.355 m to 1.0 m (10 % drift) with DisplacementControl" \
    [expr {$completed && $uNow >= $uTarget - 1e-9}]
checkTrue "the run is past the peak: final shear below 90 % of the peak ($vNow < 0.9 * $vMax)" \
    [expr {$vNow < 0.9 * $vMax}]
finish
