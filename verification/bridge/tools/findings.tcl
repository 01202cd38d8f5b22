# SPDX-License-Identifier: MIT
# The case study against the paper's five findings (Zhu, Abe and Fujino 2004, three-span isolated
# bridge under the Takatori record), generated from the numbers of the runs only: every
# comparison is written "before -> after (change %, word)" with the word decided by
# findingChange below, so a sentence cannot say "reduces" when the numbers do not.
# verification/bridge/report-findings.tcl checks this with synthetic numbers.
#
# Input: run dicts of bridge.tcl's runCase (keys peak, last, case, motion, scale), a list per
# motion in the order nopound pound countermeasure; the ladder, a list of dicts {scale case peak
# completed}; the serviceability limits.

namespace eval findings {
  # A change smaller than this fraction of the larger value is "about the same".
  variable sameFraction 0.05
  # Shear strain of bearing failure and of the design limit (yoshidaBearing -limits defaults).
  variable failureStrain 3.0
  variable designStrain 2.5
  # Below these sizes a quantity is no motion at all (a change between two of them is "about the
  # same", whatever its percentage): 1 mm, and 1e-4 rad (0.5 mm at the girders' 5 m half-width).
  # Without them a motion along the bridge axis, with rotations of 1e-7 rad, would "reduce" them.
  variable noMotion {m 0.001 rad 0.0001}
}

# Word for the change from `before` to `after` (magnitudes): "reduces", "increases" or "about
# the same" (|after - before| < sameFraction * max(|before|, |after|), or both below the unit's
# noMotion size).
proc findings::changeWord {before after {unit ""}} {
  variable sameFraction
  variable noMotion
  set a [expr {abs($before)}]; set b [expr {abs($after)}]
  set ref [expr {max($a, $b)}]
  set floor [expr {[dict exists $noMotion $unit] ? [dict get $noMotion $unit] : 0.0}]
  # the floor is judged on the value as the report prints it (to the floor's own digit), so that
  # "0.001 -> 0.000 m" is a motion that stopped, as a reader of the printed numbers sees it
  set printed [expr {$floor > 0.0 ? round($ref / $floor) * $floor : $ref}]
  if {$ref == 0.0 || $printed < $floor || abs($b - $a) < $sameFraction * $ref} { return "about the same" }
  return [expr {$b < $a ? "reduces" : "increases"}]
}

# "0.422 -> 0.301 m (-28.7 %, reduces)": the one form in which a comparison is written.
proc findings::compare {before after unit {digits 3}} {
  set a [expr {abs($before)}]; set b [expr {abs($after)}]
  set pct [expr {$a > 0.0 ? 100.0 * ($b - $a) / $a : 0.0}]
  return [format "%.${digits}f -> %.${digits}f %s (%+.1f %%, %s)" $a $b $unit $pct [changeWord $a $b $unit]]
}

# --- quantities of one run ---------------------------------------------------------------------
proc findings::bearingTagsOf {r} {
  set tags {}
  foreach k [dict keys [dict get $r peak] strain*] { lappend tags [string range $k 6 end] }
  return [lsort -integer $tags]
}
# Pier of a bearing tag: bridge.tcl's numbering when it is loaded, else the three-span one.
proc findings::pierOf {bt} {
  if {[info commands ::bearingPlace] ne ""} { return [lindex [::bearingPlace $bt] 0] }
  return [expr {$bt / 1000}]
}
# Joint numbers 1 ... n-1 and girder numbers 1 ... n of a run (any number of spans).
proc findings::jointsOf {r} {
  set js {}
  for {set j 1} {[dict exists $r peak gap${j}x]} {incr j} { lappend js $j }
  return $js
}
proc findings::girdersOf {r} {
  set ss {}
  for {set s 1} {[dict exists $r peak rot$s]} {incr s} { lappend ss $s }
  return $ss
}
# Largest longitudinal bearing displacement (top minus bottom) over every bearing, m.
proc findings::bearingLong {r} {
  set m 0.0
  foreach bt [bearingTagsOf $r] { set m [expr {max($m, abs([dict get $r peak bx$bt]))}] }
  return $m
}
# The middle span, as the paper's figures show it: girder n/2 + 1, its two girder ends (the
# bearing tags of sorted ends 2(s-1) and 2(s-1)+1) and the joints at its ends.
proc findings::midGirder {r} { return [expr {[llength [girdersOf $r]] / 2 + 1}] }
proc findings::midBearingLong {r} {
  set s [midGirder $r]
  set m 0.0
  foreach bt [lrange [bearingTagsOf $r] [expr {2 * $s - 2}] [expr {2 * $s - 1}]] {
    set m [expr {max($m, abs([dict get $r peak bx$bt]))}]
  }
  return $m
}
proc findings::midJoints {r} {
  set s [midGirder $r]
  set js {}
  foreach j [list [expr {$s - 1}] $s] { if {[dict exists $r peak gap${j}x]} { lappend js $j } }
  return $js
}
proc findings::midGapMax {r dir} {
  set m 0.0
  foreach j [midJoints $r] { set m [expr {max($m, abs([dict get $r peak gap$j$dir]))}] }
  return $m
}
proc findings::midRot {r} { return [expr {abs([dict get $r peak rot[midGirder $r]])}] }
# Largest |gap| of the joints in direction x, y or z; which = peak or last (residual).
proc findings::gapMax {r dir {which peak}} {
  set m 0.0
  foreach j [jointsOf $r] {
    if {[dict exists $r $which gap$j$dir]} { set m [expr {max($m, abs([dict get $r $which gap$j$dir]))}] }
  }
  return $m
}
# Largest opening (positive longitudinal gap) during the motion over the joints and, where the run
# has them, the unit's end joints (against the next unit or the backwall), m. The peak dict holds
# the gap of largest magnitude, so an opening smaller than the closing is not there; the residual
# opening is used too.
proc findings::openingMax {r} {
  set m 0.0
  foreach which {peak last} {
    foreach j [jointsOf $r] { set m [expr {max($m, [dict get $r $which gap${j}x])}] }
  }
  foreach j [jointsOf $r] { if {[dict exists $r peak open$j]} { set m [expr {max($m, [dict get $r peak open$j])}] } }
  foreach e {0 1} { if {[dict exists $r peak endopen$e]} { set m [expr {max($m, [dict get $r peak endopen$e])}] } }
  return $m
}
# Largest closing (magnitude of the most negative longitudinal gap) of the two joints, m.
proc findings::closingMax {r} {
  set m 0.0
  foreach j [jointsOf $r] {
    set c [expr {[dict exists $r peak close$j] ? [dict get $r peak close$j] : min([dict get $r peak gap${j}x], 0.0)}]
    set m [expr {max($m, -$c)}]
  }
  return $m
}
# Tag of the bearing with the largest longitudinal displacement.
proc findings::bearingLongTag {r} {
  set m -1.0; set tag ""
  foreach bt [bearingTagsOf $r] {
    if {abs([dict get $r peak bx$bt]) > $m} { set m [expr {abs([dict get $r peak bx$bt])}]; set tag $bt }
  }
  return $tag
}
proc findings::rotMax {r} {
  set m 0.0
  foreach s [girdersOf $r] { set m [expr {max($m, abs([dict get $r peak rot$s]))}] }
  return $m
}
proc findings::strainMax {r} {
  set m 0.0
  foreach bt [bearingTagsOf $r] { set m [expr {max($m, [dict get $r peak strain$bt])}] }
  return $m
}
proc findings::failedCount {r} {
  variable failureStrain
  set n 0
  # bearings that failed, counted one by one where the run says how many of each girder end's
  # bearings failed (several bearings across the width), else the girder ends past failure
  foreach bt [bearingTagsOf $r] {
    if {[dict exists $r peak failed$bt]} {
      incr n [dict get $r peak failed$bt]
    } elseif {[dict get $r peak strain$bt] >= $failureStrain} { incr n }
  }
  return $n
}
# Piers 1 ... n+1 of a run, and the largest pier drift ratio (peak or last, i.e. residual).
proc findings::piersOf {r} {
  # every pier with a drift (an abutment at an end has none)
  set ps {}
  foreach k [dict keys [dict get $r peak] drift*] {
    set p [string range $k 5 end]
    if {[string is integer -strict $p]} { lappend ps $p }
  }
  return [lsort -integer $ps]
}
proc findings::driftMax {r {which peak}} {
  set m 0.0
  foreach p [piersOf $r] { if {[dict exists $r $which drift$p]} { set m [expr {max($m, [dict get $r $which drift$p])}] } }
  return $m
}
proc findings::pct {x} { return [format "%.0f%%" [expr {100.0 * $x}]] }
proc findings::motionName {runs} {
  set m [dict get [lindex $runs 0] motion]
  return [expr {[string match *pulse* $m] ? "pulse" : "record"}]
}

# --- serviceability ------------------------------------------------------------------------------
# limits: a dict with step (residual vertical step at a joint, m), residual (residual longitudinal
# and transverse offset of a joint, m), drift (residual pier drift ratio), seatEdge (a girder end's
# travel to the cap's edge, m) and seatJRA (the JRA minimum seat length S_EM, m).
# Largest residual longitudinal offset over the joints and, where the run has them, the unit's end
# joints (against the next unit or the backwall).
proc findings::residualOpening {r} {
  set m [gapMax $r x last]
  foreach e {0 1} { if {[dict exists $r last endgap$e]} { set m [expr {max($m, abs([dict get $r last endgap$e]))}] } }
  return $m
}
# Largest residual offset over the joints and the unit's end joints in direction y or z, m.
proc findings::residualGap {r dir} {
  set m [gapMax $r $dir last]
  foreach e {0 1} { if {[dict exists $r last endgap$e$dir]} { set m [expr {max($m, abs([dict get $r last endgap$e$dir]))}] } }
  return $m
}
# Largest travel of a girder end towards the edge of its seat (peak over the ends), m.
proc findings::seatTravel {r} {
  set m 0.0
  foreach k [dict keys [dict get $r peak] seat*] {
    if {[string is integer -strict [string range $k 4 end]]} { set m [expr {max($m, [dict get $r peak $k])}] }
  }
  return $m
}
# {passable 0|1 word text} for one run: the residual state (step, offsets, pier drift) and the
# seat against the limits; the peak opening is damage to the joint, not part of the verdict.
proc findings::serviceability {r limits} {
  set checks [list [list "residual vertical step" [residualGap $r z] [dict get $limits step]] \
                  [list "residual longitudinal" [residualOpening $r] [dict get $limits residual]] \
                  [list "residual transverse" [residualGap $r y] [dict get $limits residual]]]
  if {[llength [piersOf $r]] > 0} {
    lappend checks [list "residual pier drift ratio" [driftMax $r last] [dict get $limits drift]]
  }
  lappend checks [list "travel towards the seat's edge" [seatTravel $r] [dict get $limits seatEdge]]
  set ok 1
  set parts {}
  foreach c $checks {
    lassign $c label v limit
    set pass [expr {$v <= $limit}]
    if {!$pass} { set ok 0 }
    lappend parts [format "%s %.4f %s %.4f" $label $v [expr {$pass ? "<=" : ">"}] $limit]
  }
  return [list $ok [expr {$ok ? "passable" : "not passable"}] [join $parts ", "]]
}
# The limits with those that are ours (step, residual) multiplied by f.
proc findings::scaledLimits {limits f} {
  foreach key {step residual} { dict set limits $key [expr {$f * [dict get $limits $key]}] }
  return $limits
}

# --- the five findings -------------------------------------------------------------------------
# motions: a list of run lists (one per motion, each nopound pound countermeasure). Returns a list
# of dicts {n paper ours verdict why}.
proc findings::paperFindings {motions ladder limits} {
  set rows {}
  # (1) pounding reduces the longitudinal displacement of the superstructure
  set ours {}; set agree {}
  # judged on the middle span, as the paper's figure shows it; the extremes over the bridge beside
  foreach runs $motions {
    lassign $runs rn rp rc
    set w [changeWord [midBearingLong $rn] [midBearingLong $rp] m]
    lappend agree [expr {$w eq "reduces"}]
    lappend ours "[motionName $runs], middle span (G[midGirder $rn]), longitudinal bearing displacement, no pounding -> pounding: [compare [midBearingLong $rn] [midBearingLong $rp] m]; over the bridge, largest: [compare [bearingLong $rn] [bearingLong $rp] m]; largest closing of a joint (girder ends moving towards each other): [compare [closingMax $rn] [closingMax $rp] m]"
  }
  set why ""
  if {![all $agree]} { set why "[whereLargest $motions] [whyPounding $ladder]" }
  lappend rows [dict create n 1 paper "Pounding greatly reduces the large longitudinal displacement of the superstructure that the rubber bearings allow." \
      ours [join $ours "; "] verdict [verdict $motions $agree] why $why]

  # (2) the countermeasure works longitudinally and in rotation about the vertical
  set ours {}; set agree {}
  foreach runs $motions {
    lassign $runs rn rp rc
    set wx [changeWord [midGapMax $rp x] [midGapMax $rc x] m]
    set wr [changeWord [midRot $rp] [midRot $rc] rad]
    lappend agree [expr {$wx eq "reduces" && $wr eq "reduces"}]
    lappend ours "[motionName $runs], middle span (G[midGirder $rp] and its joints), pounding -> countermeasure: peak longitudinal gap [compare [midGapMax $rp x] [midGapMax $rc x] m], peak girder rotation about the vertical [compare [midRot $rp] [midRot $rc] rad 4]; over the bridge, largest: gap [compare [gapMax $rp x] [gapMax $rc x] m], rotation [compare [rotMax $rp] [rotMax $rc] rad 4]"
  }
  set why ""
  if {![all $agree]} { set why [whyDevices $motions x] }
  lappend rows [dict create n 2 paper "The countermeasure (restrainers and bumpers) works in the longitudinal and the rotational directions." \
      ours [join $ours "; "] verdict [verdict $motions $agree] why $why]

  # (3) peak and residual longitudinal gaps do not harm serviceability: judged on the cases with
  # pounding (without it the girders overlap: a reference, not a bridge), residual longitudinal
  # offsets within the joint's range and no girder end travelling off its seat
  set ours {}; set agree {}
  foreach runs $motions {
    set all 1
    set parts {}
    foreach r [lrange $runs 1 end] {
      set res [residualOpening $r]; set seat [seatTravel $r]
      set ok [expr {$res <= [dict get $limits residual] && $seat <= [dict get $limits seatEdge]}]
      if {!$ok} { set all 0 }
      lappend parts [format "%s: residual longitudinal offset %.3f m %s %.3f m, travel towards the seat's edge %.3f m %s %.3f m (JRA S_EM %.2f m)" \
          [dict get $r case] $res [expr {$res <= [dict get $limits residual] ? "<=" : ">"}] [dict get $limits residual] \
          $seat [expr {$seat <= [dict get $limits seatEdge] ? "<=" : ">"}] [dict get $limits seatEdge] [dict get $limits seatJRA]]
    }
    lappend agree $all
    lappend ours "[motionName $runs]: [join $parts {; }]"
  }
  lappend rows [dict create n 3 paper "Peak and residual longitudinal gaps are not large enough to harm serviceability." \
      ours [join $ours "; "] verdict [verdict $motions $agree] \
      why [expr {[all $agree] ? "" : [whyService $motions $limits]}]]

  # (4) the countermeasure reduces the peak transverse gap
  set ours {}; set agree {}
  foreach runs $motions {
    lassign $runs rn rp rc
    set w [changeWord [gapMax $rp y] [gapMax $rc y] m]
    lappend agree [expr {$w eq "reduces"}]
    lappend ours "[motionName $runs], peak transverse gap, pounding -> countermeasure: [compare [gapMax $rp y] [gapMax $rc y] m]"
  }
  lappend rows [dict create n 4 paper "The countermeasure reduces the peak transverse gap." \
      ours [join $ours "; "] verdict [verdict $motions $agree] why [expr {[all $agree] ? "" : [whyDevices $motions y]}]]

  # (5) rubber bearings fail (300 %), which can leave unevenness between girders
  set ours {}; set agree {}
  foreach runs $motions {
    set parts {}
    set any 0
    foreach r $runs {
      set n [failedCount $r]
      if {$n > 0} { set any 1 }
      lappend parts [format "%s %s, %d failed, residual vertical offset %.3f m" [dict get $r case] [pct [strainMax $r]] $n [residualGap $r z]]
    }
    lappend agree $any
    lappend ours "[motionName $runs], largest bearing shear strain: [join $parts {; }]"
  }
  lappend rows [dict create n 5 paper "Rubber bearings fail (300 % shear strain), which can leave unevenness between girders." \
      ours [join $ours "; "] verdict [verdict $motions $agree] why [expr {[all $agree] ? "" : [whyFailure $ladder]}]]
  return $rows
}

proc findings::all {flags} {
  foreach f $flags { if {!$f} { return 0 } }
  return 1
}
# "agrees" when every motion agrees, "differs" when none does, else which motions agree.
proc findings::verdict {motions flags} {
  if {[all $flags]} { return "agrees" }
  set yes {}; set no {}
  foreach runs $motions f $flags { if {$f} { lappend yes [motionName $runs] } else { lappend no [motionName $runs] } }
  if {[llength $yes] == 0} { return "differs" }
  return "agrees for [join $yes {, }], differs for [join $no {, }]"
}

# Ladder rows of one case, sorted by scale.
proc findings::ladderOf {ladder case} {
  set rows {}
  foreach l $ladder { if {[dict get $l case] eq $case && [dict get $l completed]} { lappend rows $l } }
  return [lsort -real -index 0 [lmap l $rows { list [dict get $l scale] $l }]]
}
proc findings::firstFailureScale {ladder case} {
  foreach pair [ladderOf $ladder $case] {
    lassign $pair s l
    if {[failedCount [dict create peak [dict get $l peak]]] > 0} { return $s }
  }
  return ""
}

# Why pounding does not reduce the displacement: the ladder of scales, no pounding against pounding.
proc findings::whyPounding {ladder} {
  # the middle span's displacement, as finding 1 is judged
  if {[llength $ladder] == 0} { return "no scale ladder was run (case all with the default motion runs it)" }
  set parts {}
  set reducedFrom ""
  foreach pn [ladderOf $ladder nopound] pp [ladderOf $ladder pound] {
    lassign $pn s ln
    lassign $pp sp lp
    if {$s != $sp} { continue }
    set rn [dict create peak [dict get $ln peak]]; set rp [dict create peak [dict get $lp peak]]
    set w [changeWord [midBearingLong $rn] [midBearingLong $rp] m]
    if {$w eq "reduces" && $reducedFrom eq ""} { set reducedFrom $s }
    lappend parts "x$s: [compare [midBearingLong $rn] [midBearingLong $rp] m] at [pct [strainMax $rn]] bearing strain without pounding"
  }
  set text "Record scaled, no pounding -> pounding, the middle span's longitudinal bearing displacement: [join $parts {; }]."
  set fail [firstFailureScale $ladder nopound]
  if {$reducedFrom ne ""} {
    append text " Pounding first reduces it at scale $reducedFrom"
    append text [expr {$fail ne "" ? ", and bearings fail without pounding from scale $fail" : ""}]
    append text [expr {$reducedFrom == 1.0 ? ": at the record's own scale too, so the difference lies in the motion used for the verdict, not in the scale." : ": the paper's mechanism is there; at the record's own scale our bridge (our dimensions: the paper does not publish its) does not move far enough for it, so the difference is the model."}]
  } else {
    append text " Pounding does not reduce it at any scale run, so the level of shaking (our bearings' size against the record) does not explain the difference: in this model the impacts at the joints do not limit the girders' longitudinal displacement at any of these levels."
  }
  return $text
}

proc findings::whyFailure {ladder} {
  if {[llength $ladder] == 0} { return "no scale ladder was run (case all with the default motion runs it)" }
  set parts {}
  foreach c {nopound pound} {
    set s [firstFailureScale $ladder $c]
    set top [lindex [ladderOf $ladder $c] end]
    if {$s ne ""} {
      set l [lindex [lsearch -index 0 -inline -real [ladderOf $ladder $c] $s] 1]
      set step [expr {[dict exists $l last] ? [format ", leaving a residual vertical step of %.3f m at a joint" [residualGap $l z]] : ""}]
      lappend parts "$c: bearings reach 300 % from scale $s of the record$step"
    } elseif {$top ne ""} {
      lappend parts "$c: no bearing fails up to scale [lindex $top 0] ([pct [strainMax [dict create peak [dict get [lindex $top 1] peak]]]])"
    }
  }
  set text "[join $parts {; }]."
  if {[firstFailureScale $ladder nopound] ne "" || [firstFailureScale $ladder pound] ne ""} {
    append text " The bearings fail once the shaking is strong enough for their size (rubber area and thickness are ours): the difference is the model's dimensions, not the physics."
  }
  return $text
}

# Which of finding 3's limits fail, with the largest value of each over the cases with pounding,
# and the factor on our limit of the residual offset at which the verdict would turn.
proc findings::whyService {motions limits} {
  set res 0.0; set seat 0.0
  foreach runs $motions {
    foreach r [lrange $runs 1 end] {
      set res [expr {max($res, [residualOpening $r])}]
      set seat [expr {max($seat, [seatTravel $r])}]
    }
  }
  set lim [dict get $limits residual]
  set parts [list [format "largest residual longitudinal offset %.3f m %s the %.3f m limit (ours)" $res [expr {$res > $lim ? "exceeds" : "is within"}] $lim] \
                  [format "largest travel towards a seat's edge %.3f m %s the %.3f m seat" $seat [expr {$seat > [dict get $limits seatEdge] ? "exceeds" : "is within"}] [dict get $limits seatEdge]]]
  set text "[join $parts {; }]."
  if {$res > $lim && $seat <= [dict get $limits seatEdge]} {
    append text [format " Only the residual offset fails, against a limit of ours: with a joint %.1f times as tolerant the verdict turns." [expr {$res / $lim}]]
  }
  return $text
}

# Where the largest bearing displacement is: at an end of the bridge (PC1 or the last pier, where
# the model has no neighbour to pound on) or at a joint.
proc findings::whereLargest {motions} {
  set parts {}
  foreach runs $motions {
    lassign $runs rn rp
    set tags [bearingTagsOf $rp]
    set bt [bearingLongTag $rp]
    set end [expr {$bt == [lindex $tags 0] || $bt == [lindex $tags end]}]
    set beyond [expr {[info exists ::endCondition] ? $::endCondition : "free"}]
    set where [expr {!$end ? "a joint" : ($beyond eq "free" ? "an end of the bridge, where the model has no neighbour (no abutment) to pound on" : "an end of the bridge, next to the [expr {$beyond eq "adjacent" ? "next unit's girder" : "abutment's backwall"}]")}]
    lappend parts "[motionName $runs]: with pounding the largest longitudinal bearing displacement is at bearing $bt (PC[findings::pierOf $bt]), [format %.3f [expr {abs([dict get $rp peak bx$bt])}]] m, at $where"
  }
  return "[join $parts {; }]."
}

# Why the devices do not reduce a quantity: how far the joints move with pounding alone against
# the devices' free travel (dir x: restrainer slack and bumper clearance; y: transverse clearance),
# and for x the rotation about the vertical.
proc findings::whyDevices {motions dir} {
  set parts {}
  set engaged 0
  foreach runs $motions {
    lassign $runs rn rp rc
    if {$dir eq "x"} {
      set open [openingMax $rp]; set close [closingMax $rp]
      if {$open > $::restrainerSlack || $close > $::bumperClearance} { set engaged 1 }
      lappend parts [format "%s: with pounding alone the joints open up to %.3f m (restrainer slack %.3f m) and close up to %.3f m (bumper clearance %.3f m); rotation about the vertical %s" \
          [motionName $runs] $open $::restrainerSlack $close $::bumperClearance [compare [rotMax $rp] [rotMax $rc] rad 4]]
    } else {
      set g [gapMax $rp y]
      if {$g > $::transverseSlack} { set engaged 1 }
      lappend parts [format "%s: with pounding alone the transverse gap reaches %.3f m, %.3f m %s the transverse devices' clearance of %.3f m" \
          [motionName $runs] $g [expr {abs($g - $::transverseSlack)}] [expr {$g > $::transverseSlack ? "beyond" : "short of"}] $::transverseSlack]
    }
  }
  set text "[join $parts {; }]."
  if {!$engaged} {
    append text " The joints stay within the devices' free travel, so the devices never act: the difference is the device settings of the model (ours), not the physics."
  } elseif {$dir eq "x"} {
    append text " The devices do act longitudinally, on both sides of the girders, so that their couple resists the relative rotation about the vertical too; where the rotation is not reduced, the devices' slack and stiffness (see the parameter table) decide how much of it they take."
  } else {
    append text " The devices act only on the part of the transverse gap beyond their clearance; how much they reduce it follows from that clearance and their stiffness, which are the model's (ours): the difference is the model's device settings."
  }
  return $text
}

# Markdown: the findings table and the serviceability verdicts.
proc findings::markdown {motions ladder limits} {
  variable sameFraction
  set out "A change is \"about the same\" when it is below [format %.0f [expr {100 * $sameFraction}]] % of the larger value, or when both values are below 1 mm (1e-4 rad for rotations: no motion); otherwise it \"reduces\" or \"increases\".\n\n"
  append out "| # | finding of the paper | our model (numbers) | agrees / differs | why |\n|---|---|---|---|---|\n"
  foreach row [paperFindings $motions $ladder $limits] {
    append out "| [dict get $row n] | [dict get $row paper] | [dict get $row ours] | [dict get $row verdict] | [dict get $row why] |\n"
  }
  append out "\n## Serviceability\n\n"
  append out "Traffic after the earthquake. Limits and their sources:\n\n"
  append out "| quantity | limit | source |\n|---|---:|---|\n"
  append out [format "| girder end's travel towards the edge of its seat (m) | %.3f | this model's seat: half the cap length less half the gap; the JRA minimum seat length S_EM = 0.7 + 0.005 l is %.2f m (JRA Specifications for Highway Bridges Part V, 2002, 16.2) |\n" [dict get $limits seatEdge] [dict get $limits seatJRA]]
  append out [format "| residual pier drift ratio | %.3f | JRA Part V (1996, 2002): residual displacement of an RC pier <= h/100 |\n" [dict get $limits drift]]
  append out [format "| residual vertical step at a joint (m) | %.3f | ours: no published number for a step traffic can cross was found; a step an emergency vehicle crosses at low speed |\n" [dict get $limits step]]
  append out [format "| residual longitudinal and transverse offset of a joint (m) | %.3f | ours: a finger joint made for the %.3f m gap taken to accommodate +- its gap |\n\n" [dict get $limits residual] $::jointGap]
  append out "The case without pounding is the reference (the girders pass through each other), not a design: its line is given for comparison. The peak opening of a joint during the motion is damage to the joint (its fingers), reported beside the verdict, not part of it.\n\n"
  foreach runs $motions {
    foreach r $runs {
      lassign [serviceability $r $limits] ok word text
      set label [expr {[dict get $r case] eq "nopound" ? "nopound (reference)" : [dict get $r case]}]
      append out "- [motionName $runs], $label: **$word** ($text); peak opening of a joint [format %.3f [openingMax $r]] m\n"
    }
  }
  # How the verdicts move with the limits that are ours (step and residual offset)
  set factors {0.5 1.0 2.0}
  append out "\nThe verdicts with our limits (vertical step, residual offset) halved and doubled:\n\n"
  append out "| motion, case | [join [lmap f $factors {format "step %.3f m, offset %.3f m" [expr {$f * [dict get $limits step]}] [expr {$f * [dict get $limits residual]}]}] { | }] |\n"
  append out "|---|[string repeat ---| [llength $factors]]\n"
  foreach runs $motions {
    foreach r $runs {
      set cells {}
      foreach f $factors { lappend cells [lindex [serviceability $r [scaledLimits $limits $f]] 1] }
      append out "| [motionName $runs], [dict get $r case] | [join $cells { | }] |\n"
    }
  }
  return $out
}
