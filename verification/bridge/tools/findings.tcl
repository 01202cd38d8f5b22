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
}

# Word for the change from `before` to `after` (magnitudes): "reduces", "increases" or "about
# the same" (|after - before| < sameFraction * max(|before|, |after|)).
proc findings::changeWord {before after} {
  variable sameFraction
  set a [expr {abs($before)}]; set b [expr {abs($after)}]
  set ref [expr {max($a, $b)}]
  if {$ref == 0.0 || abs($b - $a) < $sameFraction * $ref} { return "about the same" }
  return [expr {$b < $a ? "reduces" : "increases"}]
}

# "0.422 -> 0.301 m (-28.7 %, reduces)": the one form in which a comparison is written.
proc findings::compare {before after unit {digits 3}} {
  set a [expr {abs($before)}]; set b [expr {abs($after)}]
  set pct [expr {$a > 0.0 ? 100.0 * ($b - $a) / $a : 0.0}]
  return [format "%.${digits}f -> %.${digits}f %s (%+.1f %%, %s)" $a $b $unit $pct [changeWord $a $b]]
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
# Largest |gap| of the joints in direction x, y or z; which = peak or last (residual).
proc findings::gapMax {r dir {which peak}} {
  set m 0.0
  foreach j [jointsOf $r] {
    if {[dict exists $r $which gap$j$dir]} { set m [expr {max($m, abs([dict get $r $which gap$j$dir]))}] }
  }
  return $m
}
# Largest opening (positive longitudinal gap) of the two joints during the motion, m. The peak
# dict holds the gap of largest magnitude, so an opening smaller than the closing is not there;
# the residual opening is used too.
proc findings::openingMax {r} {
  set m 0.0
  foreach which {peak last} {
    foreach j [jointsOf $r] { set m [expr {max($m, [dict get $r $which gap${j}x])}] }
  }
  foreach j [jointsOf $r] { if {[dict exists $r peak open$j]} { set m [expr {max($m, [dict get $r peak open$j])}] } }
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
  foreach bt [bearingTagsOf $r] { if {[dict get $r peak strain$bt] >= $failureStrain} { incr n } }
  return $n
}
proc findings::pct {x} { return [format "%.0f%%" [expr {100.0 * $x}]] }
proc findings::motionName {runs} {
  set m [dict get [lindex $runs 0] motion]
  return [expr {[string match *pulse* $m] ? "pulse" : "record"}]
}

# --- serviceability ------------------------------------------------------------------------------
# {passable 0|1 text} for one run: the peak opening and the residual longitudinal and transverse
# offsets of both joints against the limits.
proc findings::serviceability {r maxOpening maxResidual} {
  set open [openingMax $r]
  set resX [gapMax $r x last]
  set resY [gapMax $r y last]
  set checks [list [list "peak opening" $open $maxOpening] [list "residual longitudinal" $resX $maxResidual] \
                  [list "residual transverse" $resY $maxResidual]]
  set ok 1
  set parts {}
  foreach c $checks {
    lassign $c label v limit
    set pass [expr {$v <= $limit}]
    if {!$pass} { set ok 0 }
    lappend parts [format "%s %.3f m %s %.3f m" $label $v [expr {$pass ? "<=" : ">"}] $limit]
  }
  return [list $ok [expr {$ok ? "passable" : "not passable"}] [join $parts ", "]]
}

# --- the five findings -------------------------------------------------------------------------
# motions: a list of run lists (one per motion, each nopound pound countermeasure). Returns a list
# of dicts {n paper ours verdict why}.
proc findings::paperFindings {motions ladder limits} {
  lassign $limits maxOpening maxResidual
  set rows {}
  # (1) pounding reduces the longitudinal displacement of the superstructure
  set ours {}; set agree {}
  foreach runs $motions {
    lassign $runs rn rp rc
    set w [changeWord [bearingLong $rn] [bearingLong $rp]]
    lappend agree [expr {$w eq "reduces"}]
    lappend ours "[motionName $runs], largest longitudinal bearing displacement, no pounding -> pounding: [compare [bearingLong $rn] [bearingLong $rp] m]; largest closing of a joint (girder ends moving towards each other): [compare [closingMax $rn] [closingMax $rp] m]"
  }
  set why ""
  if {![all $agree]} { set why "[whereLargest $motions] [whyPounding $ladder]" }
  lappend rows [dict create n 1 paper "Pounding greatly reduces the large longitudinal displacement of the superstructure that the rubber bearings allow." \
      ours [join $ours "; "] verdict [verdict $motions $agree] why $why]

  # (2) the countermeasure works longitudinally and in rotation about the vertical
  set ours {}; set agree {}
  foreach runs $motions {
    lassign $runs rn rp rc
    set wx [changeWord [gapMax $rp x] [gapMax $rc x]]
    set wr [changeWord [rotMax $rp] [rotMax $rc]]
    lappend agree [expr {$wx eq "reduces" && $wr eq "reduces"}]
    lappend ours "[motionName $runs], pounding -> countermeasure: peak longitudinal gap [compare [gapMax $rp x] [gapMax $rc x] m], peak girder rotation about the vertical [compare [rotMax $rp] [rotMax $rc] rad 4]"
  }
  set why ""
  if {![all $agree]} { set why [whyDevices $motions x] }
  lappend rows [dict create n 2 paper "The countermeasure (restrainers and bumpers) works in the longitudinal and the rotational directions." \
      ours [join $ours "; "] verdict [verdict $motions $agree] why $why]

  # (3) peak and residual longitudinal gaps do not harm serviceability
  set ours {}; set agree {}
  foreach runs $motions {
    set all 1
    set parts {}
    foreach r $runs {
      lassign [serviceability $r $maxOpening $maxResidual] ok word text
      if {!$ok} { set all 0 }
      lappend parts "[dict get $r case] $word ($text)"
    }
    lappend agree $all
    lappend ours "[motionName $runs]: [join $parts {; }]"
  }
  lappend rows [dict create n 3 paper "Peak and residual longitudinal gaps are not large enough to harm serviceability." \
      ours [join $ours "; "] verdict [verdict $motions $agree] \
      why [expr {[all $agree] ? "" : [whyService $motions $maxOpening $maxResidual]}]]

  # (4) the countermeasure reduces the peak transverse gap
  set ours {}; set agree {}
  foreach runs $motions {
    lassign $runs rn rp rc
    set w [changeWord [gapMax $rp y] [gapMax $rc y]]
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
      lappend parts [format "%s %s, %d failed, residual vertical offset %.3f m" [dict get $r case] [pct [strainMax $r]] $n [gapMax $r z last]]
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
  if {[llength $ladder] == 0} { return "no scale ladder was run (case all with the default motion runs it)" }
  set parts {}
  set reducedFrom ""
  foreach pn [ladderOf $ladder nopound] pp [ladderOf $ladder pound] {
    lassign $pn s ln
    lassign $pp sp lp
    if {$s != $sp} { continue }
    set rn [dict create peak [dict get $ln peak]]; set rp [dict create peak [dict get $lp peak]]
    set w [changeWord [bearingLong $rn] [bearingLong $rp]]
    if {$w eq "reduces" && $reducedFrom eq ""} { set reducedFrom $s }
    lappend parts "x$s: [compare [bearingLong $rn] [bearingLong $rp] m] at [pct [strainMax $rn]] bearing strain without pounding"
  }
  set text "Record scaled, no pounding -> pounding, largest longitudinal bearing displacement: [join $parts {; }]."
  set fail [firstFailureScale $ladder nopound]
  if {$reducedFrom ne ""} {
    append text " Pounding reduces it from scale $reducedFrom on"
    append text [expr {$fail ne "" ? ", and bearings fail without pounding from scale $fail" : ""}]
    append text ": the paper's mechanism is there; at the record's own scale our bridge (our dimensions: the paper does not publish its) does not move far enough for it, so the difference is the model."
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
      lappend parts "$c: bearings reach 300 % from scale $s of the record"
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

# Which serviceability limits fail, with the largest value of each quantity over the runs.
proc findings::whyService {motions maxOpening maxResidual} {
  set open 0.0; set res 0.0
  foreach runs $motions {
    foreach r $runs {
      set open [expr {max($open, [openingMax $r])}]
      set res [expr {max($res, [gapMax $r x last], [gapMax $r y last])}]
    }
  }
  set parts [list [format "largest peak opening %.3f m %s the %.3f m limit" $open [expr {$open > $maxOpening ? "exceeds" : "is within"}] $maxOpening] \
                  [format "largest residual offset %.3f m %s the %.3f m limit" $res [expr {$res > $maxResidual ? "exceeds" : "is within"}] $maxResidual]]
  set text "[join $parts {; }]."
  if {$open > $maxOpening && $res <= $maxResidual} {
    append text " Only the opening during the motion fails; judged on the residual state alone every case is passable. The limits are ours (see Serviceability): the difference lies in the criterion, which the paper does not give in numbers."
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
    set where [expr {$bt == [lindex $tags 0] || $bt == [lindex $tags end] ? "an end of the bridge, where the model has no neighbour (no abutment) to pound on" : "a joint"}]
    lappend parts "[motionName $runs]: with pounding the largest longitudinal bearing displacement is at bearing $bt (PC[findings::pierOf $bt]), [format %.3f [expr {abs([dict get $rp peak bx$bt])}]] m, at $where"
  }
  return "[join $parts {; }]."
}

# Why the devices do not reduce a quantity: how far the joints move with pounding alone against
# the devices' free travel (dir x: restrainer slack and bumper clearance; y: transverse clearance),
# and for x the rotation about the vertical, which one device on the girder axis cannot resist.
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
    append text " The devices do act longitudinally; the countermeasure here is one link on the girder axis per joint (bridge.tcl), which resists the relative movement of the axis but no relative rotation about the vertical, so it cannot reduce the rotation: the difference is the model's device layout, not the physics."
  } else {
    append text " The devices act only on the part of the transverse gap beyond their clearance; how much they reduce it follows from that clearance and their stiffness, which are the model's (ours): the difference is the model's device settings."
  }
  return $text
}

# Markdown: the findings table and the serviceability verdicts.
proc findings::markdown {motions ladder limits} {
  variable sameFraction
  lassign $limits maxOpening maxResidual
  set out "A change is \"about the same\" when it is below [format %.0f [expr {100 * $sameFraction}]] % of the larger value; otherwise it \"reduces\" or \"increases\".\n\n"
  append out "| # | finding of the paper | our model (numbers) | agrees / differs | why |\n|---|---|---|---|---|\n"
  foreach row [paperFindings $motions $ladder $limits] {
    append out "| [dict get $row n] | [dict get $row paper] | [dict get $row ours] | [dict get $row verdict] | [dict get $row why] |\n"
  }
  append out "\n## Serviceability\n\n"
  append out [format "Limits (ours; the paper's criterion has no numbers we could use): peak opening of a joint <= %.3f m and residual longitudinal and transverse offsets <= %.3f m, i.e. the expansion joint (made for the %.3f m gap) is taken to accommodate a movement of +- its gap; beyond it the fingers disengage or jam.\n\n" $maxOpening $maxResidual $::jointGap]
  foreach runs $motions {
    foreach r $runs {
      lassign [serviceability $r $maxOpening $maxResidual] ok word text
      append out "- [motionName $runs], [dict get $r case]: **$word** ($text)\n"
    }
  }
  return $out
}
