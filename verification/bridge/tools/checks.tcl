# SPDX-License-Identifier: MIT
# Checks of the case study that can fail, run at the end of bridge.tcl (so ctest and the main job
# both see them; lib/check.tcl's finish makes the exit code). For every run:
#  - it completes: every output step converged up to the end of the free vibration after the motion;
#  - no output step was accepted at the loosened tolerance (100 x tol, the last fallback);
#  - dynamic equilibrium at the end of the motion: ground reactions - weight = sum m (u'' + a_g)
#    (dynamicEquilibrium in bridge.tcl), within 1e-5 of the weight W per direction. A converged
#    Newton step leaves a force of the order K x (the next increment, < tol), about 1e-7 W here;
#    1e-5 W is 0.4 kN against inertia forces of 10 to 3000 kN at the end of the runs, so a
#    missing or mis-scaled ground acceleration (leaving out a_g at 8 s of the record leaves
#    9700 kN), a lost mass or a force that does not reach the ground fails it;
#  - pounding bounds the closing of each joint: the girder ends (their axes) cannot approach by
#    more than the gap plus the largest penetration of the joint's contact pairs. The axis closing
#    is the mean of the closings at the four symmetric contactor points of a face, each at most
#    gap + its penetration; rotations of the faces add second-order terms, r theta^2 / 2 with
#    r = 5 m and theta < 0.02 rad, so 1 mm is allowed on top.
#  - ruptured bearings that dropped rest on their seats (see run below);
# And in the study itself (case all, scale >= 1): without pounding some joint closes by more
# than its gap, so the bound above is a constraint the contact must enforce (a physical
# expectation of this bridge and these motions, not of any run a user may ask for).

namespace eval checks {}

proc checks::runName {r} {
  return "[dict get $r case] [lindex [dict get $r motion] 0] x[dict get $r scale]"
}

proc checks::run {r} {
  set name [runName $r]
  if {[dict exists $r endTime]} {
    set end [expr {$::duration + $::tailDuration}]
    checkTrue "$name: completed to t = [dict get $r endTime] s (motion $::duration s + free vibration $::tailDuration s)" \
        [expr {[dict get $r completed] && abs([dict get $r endTime] - $end) < 1e-6}]
  } else {
    checkTrue "$name: completed" [dict get $r completed]
  }
  checkTrue "$name: no output step at the loosened tolerance ([dict get $r loosened])" \
      [expr {[dict get $r loosened] == 0}]
  set e [dict get $r equilibrium]
  set W [dict get $e weight]
  foreach axis {X Y Z} res [dict get $e residual] inertia [dict get $e inertia] {
    checkAbs "$name: end equilibrium along $axis, inertia [format %.1f $inertia] kN, W [format %.0f $W] kN" \
        $res 0.0 [expr {1e-5 * $W}]
  }
  set peak [dict get $r peak]
  # Ruptured bearings (-afterFailure drop): a bearing that dropped rests on its seat or above it,
  # never deeper than the seat spring's settlement under the whole end's weight W_end / Ks (a
  # lower top means the seat contact let the girder through); a girder end whose bearings all
  # dropped rests at the seat's height: none of its bearings stands more than 5 mm above the seat.
  set seatK [dict get $::derived seatK]
  set endWeight [expr {0.5 * [dict get $::derived spanMass] * $::g}]
  foreach key [dict keys $peak seatGap*] {
    set bt [string range $key 7 end]
    set gap [dict get $peak $key]
    set low [dict get $peak seatLow$bt]
    set n [dict get $peak dropped$bt]
    checkTrue [format "%s: girder end %s, %d bearing(s) dropped, lowest seat gap %.4f m >= -W_end/Ks = %.4f m" \
        $name $bt $n $low [expr {-$endWeight / $seatK}]] [expr {$low >= -$endWeight / $seatK}]
    if {$n == [llength [endBearings $bt]]} {
      checkTrue [format "%s: girder end %s rests on its seats (every bearing dropped; highest seat gap %.4f m <= 0.005)" \
          $name $bt $gap] [expr {$gap <= 0.005}]
    }
  }
  # the end joints' residual transverse and vertical offsets are read at the other side's face:
  # its node's displacement plus the rotation times the lever equals the mean of its corners
  if {[dict exists $r endFaces]} {
    foreach f [dict get $r endFaces] {
      lassign $f what read mean
      checkAbs "$name: an end joint's far face, $what displacement as read against its corners' mean" $read $mean 1e-9
    }
  }
  if {[dict get $r case] eq "nopound"} { return }
  for {set j 1} {[dict exists $peak close$j]} {incr j} {
    set closing [expr {-[dict get $peak close$j]}]
    set pen [dict get $peak pen$j]
    checkTrue [format "%s: joint %d closes %.4f m <= gap %.3f + penetration %.4f m (+ 0.001)" \
        $name $j $closing $::jointGap $pen] [expr {$closing <= $::jointGap + $pen + 0.001}]
  }
  # the unit's end joints, against the next unit's girder or the backwall
  foreach e {0 1} side {PC1 "the last pier"} {
    if {![dict exists $peak endpen$e] || [dict get $peak endforce$e] == 0.0 && [dict get $peak endclose$e] > -$::jointGap} { continue }
    set closing [expr {-[dict get $peak endclose$e]}]
    set pen [dict get $peak endpen$e]
    checkTrue [format "%s: end joint at %s closes %.4f m <= gap %.3f + penetration %.4f m (+ 0.001)" \
        $name $side $closing $::jointGap $pen] [expr {$closing <= $::jointGap + $pen + 0.001}]
  }
}

# All runs of the study (results, the other motion, the ladder without the runs it reuses);
# study: 1 for the whole study at scale >= 1, where the joints must close without pounding.
proc checks::all {results other ladder study} {
  set runs [concat $results $other]
  foreach l $ladder {
    set dup 0
    foreach r $runs {
      if {[dict get $r case] eq [dict get $l case] && [dict get $r scale] == [dict get $l scale] &&
          [dict get $r motion] eq [dict get $l motion]} { set dup 1 }
    }
    if {!$dup} { lappend runs $l }
  }
  foreach r $runs { run $r }
  # Without pounding the girders would overlap at some joint: the contact has work to do.
  if {!$study} { return }
  foreach r $runs {
    if {[dict get $r case] ne "nopound"} { continue }
    set most 0.0
    set peak [dict get $r peak]
    for {set j 1} {[dict exists $peak close$j]} {incr j} { set most [expr {max($most, -[dict get $peak close$j])}] }
    checkTrue [format "%s: without pounding a joint closes %.3f m > gap %.3f m" [runName $r] $most $::jointGap] \
        [expr {$most > $::jointGap}]
  }
}
