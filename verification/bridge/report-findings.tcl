# SPDX-License-Identifier: MIT
# The report's findings follow from their numbers (tools/findings.tcl), checked with synthetic
# run results: every comparison "a -> b unit (p %, word)" in the generated text is parsed and its
# word and percentage are recomputed here, independently of findings.tcl; each finding's verdict
# must follow from those words; the serviceability verdicts from their limits. A finding that
# contradicts its numbers (such as "0.422 m and 0.422 m, reduced") fails this script.
source [file join [file dirname [info script]] tools findings.tcl]

set failures 0
proc check {name ok {detail ""}} {
  if {$ok} { puts "PASSED $name" } else { puts "FAILED $name $detail"; incr ::failures }
}

# Parameters of bridge.tcl the text quotes.
set restrainerSlack 0.05; set bumperClearance 0.03; set transverseSlack 0.05; set jointGap 0.05
set limits [dict create step 0.05 residual 0.05 drift 0.01 seatEdge 1.475 seatJRA 0.9]
set kSame 0.05   ;# the threshold the report states: a change below 5 % of the larger value

# A synthetic run: bearing longitudinal displacement bx (G2's start, the middle span; the others
# half of it), strain, gaps, rotation (G2; G1 half of it), residual gaps, residual vertical step,
# a girder end's travel towards its seat's edge and the piers' residual drift ratio.
proc run {case motion bx strain gx gy rot {resx 0.0} {resy 0.0} {resz 0.002} {seat 0.3} {drift 0.002}} {
  set peak [dict create gap1x $gx gap1y $gy gap1z 0.0 gap2x [expr {-0.5 * $gx}] gap2y 0.0 gap2z 0.0 \
      rot1 [expr {0.5 * $rot}] rot2 $rot rot3 0.0]
  foreach bt {1012 2011 2012 3011 3012 4011} {
    dict set peak bx$bt [expr {$bt == 2012 ? $bx : 0.5 * $bx}]
    dict set peak by$bt 0.0
    dict set peak strain$bt [expr {$bt == 3011 ? $strain : 0.5 * $strain}]
    dict set peak seat$bt [expr {$bt == 4011 ? $seat : 0.1}]
  }
  set last [dict create gap1x $resx gap1y $resy gap1z $resz gap2x 0.0 gap2y 0.0 gap2z 0.0]
  foreach p {1 2 3 4} { dict set peak drift$p [expr {2.0 * $drift}]; dict set last drift$p [expr {$p == 3 ? $drift : 0.5 * $drift}] }
  return [dict create case $case motion $motion scale 1.0 peak $peak last $last]
}

# Independent reading of a comparison: word from the two magnitudes and the unit (the report
# states that below 1 mm or 1e-4 rad nothing moves, so no change there is a reduction).
proc expectedWord {a b {unit ""}} {
  set ref [expr {max($a, $b)}]
  set floor [expr {$unit eq "m" ? 0.001 : ($unit eq "rad" ? 0.0001 : 0.0)}]
  if {$ref == 0.0 || $ref < $floor || abs($b - $a) < $::kSame * $ref} { return "about the same" }
  return [expr {$b < $a ? "reduces" : "increases"}]
}
# Every "a -> b unit (p %, word)" in text; returns the number of comparisons checked.
proc checkComparisons {label text} {
  set n 0
  foreach {all a b unit p word} [regexp -all -inline {([0-9.]+) -> ([0-9.]+) ([a-z]+) \(([-+0-9.]+) %, ([a-z ]+)\)} $text] {
    incr n
    set want [expectedWord $a $b $unit]
    check "$label: \"$all\" says $want" [expr {$word eq $want}] "(says $word)"
    set pct [expr {$a > 0 ? 100.0 * ($b - $a) / $a : 0.0}]
    check "$label: \"$all\" percentage" [expr {abs($pct - $p) <= 0.05 + 100.0 * 0.0005 / max($a, 1e-3)}] "(recomputed $pct)"
  }
  return $n
}

# --- 1. equal numbers are "about the same", never a reduction ------------------------------------
check "changeWord: equal values" [expr {[findings::changeWord 0.422 0.422] eq "about the same"}]
check "changeWord: 4 % smaller is about the same" [expr {[findings::changeWord 1.0 0.96] eq "about the same"}]
check "changeWord: 6 % smaller reduces" [expr {[findings::changeWord 1.0 0.94] eq "reduces"}]
check "changeWord: 6 % larger increases" [expr {[findings::changeWord 0.94 1.0] eq "increases"}]
check "changeWord: zero and zero" [expr {[findings::changeWord 0.0 0.0] eq "about the same"}]
check "changeWord: rotations below 1e-4 rad are no motion, whatever their ratio" [expr {[findings::changeWord 4e-7 1e-7 rad] eq "about the same"}]
check "changeWord: 1e-4 rad and more compare by ratio" [expr {[findings::changeWord 4e-4 1e-4 rad] eq "reduces"}]
check "changeWord: gaps below 1 mm (as printed, 0.000 m) are no motion" [expr {[findings::changeWord 0.0004 0.0001 m] eq "about the same"}]
check "changeWord: 0.0008 m prints as 0.001 m, a motion" [expr {[findings::changeWord 0.0008 0.0001 m] eq "reduces"}]
# a motion along the axis: no rotation with or without the devices; finding 2 cannot agree on it
set rp0 [run pound r 0.4 2.0 0.10 0.0 2e-7]
set rc0 [run countermeasure r 0.4 2.0 0.05 0.0 1e-7]
set row [lindex [findings::paperFindings [list [list [run nopound r 0.5 2.0 0.2 0.0 2e-7] $rp0 $rc0]] {} $limits] 1]
check "finding 2: rotations of 1e-7 rad are not reduced by the devices" [expr {[dict get $row verdict] eq "differs"}] [dict get $row ours]
check "compare: the 0.422/0.422 case" [expr {[findings::compare 0.422 0.422 m] eq "0.422 -> 0.422 m (+0.0 %, about the same)"}] [findings::compare 0.422 0.422 m]

# --- 2. a model that disagrees with the paper everywhere ------------------------------------------
set disagree [list \
  [list [run nopound "RSN1120_KOBE_TAK090.AT2" 0.422 2.32 0.20 0.05 0.010] \
        [run pound "RSN1120_KOBE_TAK090.AT2" 0.422 2.29 0.05 0.08 0.012 0.08] \
        [run countermeasure "RSN1120_KOBE_TAK090.AT2" 0.42 2.31 0.06 0.09 0.013]] \
  [list [run nopound "Mavroeidis-Papageorgiou pulse" 0.30 1.5 0.15 0.04 0.008] \
        [run pound "Mavroeidis-Papageorgiou pulse" 0.33 1.6 0.05 0.05 0.009] \
        [run countermeasure "Mavroeidis-Papageorgiou pulse" 0.33 1.6 0.05 0.05 0.009]]]
set ladder {}
foreach s {1.0 1.5 2.0} bx {0.422 0.60 0.80} st {2.32 3.1 3.9} {
  lappend ladder [dict create scale $s case nopound completed 1 peak [dict get [run nopound r $bx $st 0.2 0.05 0.01] peak]]
  lappend ladder [dict create scale $s case pound completed 1 peak [dict get [run pound r $bx $st 0.05 0.05 0.01] peak]]
}
set rows [findings::paperFindings $disagree $ladder $limits]
check "five findings" [expr {[llength $rows] == 5}]
set n 0
foreach row $rows { incr n [checkComparisons "disagree #[dict get $row n]" "[dict get $row ours] [dict get $row why]"] }
check "the comparisons were found and checked" [expr {$n >= 10}] "($n)"
foreach k {0 1 3 4} {
  check "disagree: finding [expr {$k + 1}] differs" [expr {[dict get [lindex $rows $k] verdict] eq "differs"}] [dict get [lindex $rows $k] verdict]
}
check "disagree: residual 0.08 m > 0.05 m with pounding (record) differs; a peak opening of 0.15 m without pounding (pulse) is the reference, not judged" \
    [expr {[dict get [lindex $rows 2] verdict] eq "agrees for pulse, differs for record"}] [dict get [lindex $rows 2] verdict]
check "disagree: equal bearing displacements are not called a reduction" \
    [regexp {record, middle span \(G2\), longitudinal bearing displacement, no pounding -> pounding: 0.422 -> 0.422 m \(\+0.0 %, about the same\)} [dict get [lindex $rows 0] ours]] [dict get [lindex $rows 0] ours]
check "disagree: finding 1's why says where the largest displacement is" [string match "*at bearing 2012 (PC2)*at a joint*" [dict get [lindex $rows 0] why]] [dict get [lindex $rows 0] why]
check "disagree: finding 1's why names the ladder and its first failure" \
    [expr {[string match "*x2.0:*" [dict get [lindex $rows 0] why]] && ![string match "*first reduces it at*" [dict get [lindex $rows 0] why]]}] [dict get [lindex $rows 0] why]
set why [findings::whyDevices [list [lindex $disagree 1]] x]
check "pulse: joints within the devices' free travel: the devices never act" \
    [string match "pulse: *open up to 0.050 m (restrainer slack 0.050 m) and close up to 0.025 m*never act*" $why] $why
check "record: a residual opening of 0.080 m passes the 0.050 m slack: the devices act" \
    [string match "*open up to 0.080 m*do act longitudinally*" [dict get [lindex $rows 1] why]] [dict get [lindex $rows 1] why]
check "disagree: transverse gap 0.08 m beyond the 0.05 m clearance: the devices act" \
    [string match "*0.080 m, 0.030 m beyond*act only on the part*" [dict get [lindex $rows 3] why]] [dict get [lindex $rows 3] why]
check "disagree: finding 3's why names the failing limits" \
    [string match "largest residual longitudinal offset 0.080 m exceeds the 0.050 m limit (ours); largest travel towards a seat's edge 0.300 m is within the 1.475 m seat. Only the residual offset fails*1.6 times*" [dict get [lindex $rows 2] why]] [dict get [lindex $rows 2] why]
check "disagree: finding 5's why gives the scale at which bearings fail" \
    [string match "*nopound: bearings reach 300 % from scale 1.5*" [dict get [lindex $rows 4] why]] [dict get [lindex $rows 4] why]

# a ladder run that keeps its residuals: the why gives the step the failed bearings leave
set ladder3 {}
foreach s {1.0 1.5} st {2.3 3.2} rz {0.001 0.288} {
  set l [run nopound r 0.5 $st 0.2 0.05 0.01 0.0 0.0 $rz]
  lappend ladder3 [dict create scale $s case nopound completed 1 peak [dict get $l peak] last [dict get $l last]]
}
set why [findings::whyFailure $ladder3]
check "finding 5's why gives the residual vertical step where bearings fail" \
    [string match "*nopound: bearings reach 300 % from scale 1.5 of the record, leaving a residual vertical step of 0.288 m at a joint*" $why] $why

# --- 3. a model that agrees with the paper everywhere ---------------------------------------------
set agree [list \
  [list [run nopound "RSN1120_KOBE_TAK090.AT2" 0.70 3.4 0.02 0.06 0.020] \
        [run pound "RSN1120_KOBE_TAK090.AT2" 0.40 3.1 0.03 0.06 0.020 0.01] \
        [run countermeasure "RSN1120_KOBE_TAK090.AT2" 0.38 2.9 0.02 0.02 0.005]]]
set rows [findings::paperFindings $agree $ladder $limits]
foreach row $rows {
  checkComparisons "agree #[dict get $row n]" [dict get $row ours]
  check "agree: finding [dict get $row n] agrees" [expr {[dict get $row verdict] eq "agrees"}] [dict get $row verdict]
  check "agree: finding [dict get $row n] needs no why" [expr {[dict get $row why] eq ""}]
}

# --- 4. one motion agrees, the other not ----------------------------------------------------------
set mixed [list [lindex $agree 0] [lindex $disagree 1]]
set row [lindex [findings::paperFindings $mixed $ladder $limits] 0]
check "mixed: verdict names the motions" [expr {[dict get $row verdict] eq "agrees for record, differs for pulse"}] [dict get $row verdict]

# --- 4b. findings 1 and 2 are judged on the middle span, the extremes over the bridge beside -------
set rn [run nopound "RSN1120_KOBE_TAK090.AT2" 0.60 2.0 0.2 0.05 0.010]
set rp [run pound "RSN1120_KOBE_TAK090.AT2" 0.40 2.0 0.05 0.05 0.010]
dict set rp peak bx1012 0.9   ;# the end girder's outer end moves further with pounding
set rc [run countermeasure "RSN1120_KOBE_TAK090.AT2" 0.40 2.0 0.04 0.05 0.005]
dict set rc peak rot1 0.02    ;# an end girder turns more with the devices; the middle one less
set rows [findings::paperFindings [list [list $rn $rp $rc]] $ladder $limits]
check "middle span: finding 1 agrees though the largest displacement grows at an end" \
    [expr {[dict get [lindex $rows 0] verdict] eq "agrees"}] [dict get [lindex $rows 0] verdict]
check "middle span: finding 1 gives the extreme beside" \
    [string match "*middle span (G2)*0.600 -> 0.400 m*over the bridge, largest: 0.600 -> 0.900 m (+50.0 %, increases)*" [dict get [lindex $rows 0] ours]] [dict get [lindex $rows 0] ours]
check "middle span: finding 2 agrees on G2's rotation though G1 turns more" \
    [expr {[dict get [lindex $rows 1] verdict] eq "agrees"}] [dict get [lindex $rows 1] verdict]
checkComparisons "middle span #1" [dict get [lindex $rows 0] ours]
checkComparisons "middle span #2" [dict get [lindex $rows 1] ours]

# --- 5. pounding reduces the displacement from some scale on: the why says so and which scale ------
set ladder2 {}
foreach s {1.0 1.5 2.0} bn {0.422 0.60 0.80} bp {0.422 0.50 0.60} {
  lappend ladder2 [dict create scale $s case nopound completed 1 peak [dict get [run nopound r $bn 2.0 0.2 0.05 0.01] peak]]
  lappend ladder2 [dict create scale $s case pound completed 1 peak [dict get [run pound r $bp 2.0 0.05 0.05 0.01] peak]]
}
set why [findings::whyPounding $ladder2]
checkComparisons "ladder why" $why
check "ladder: reduction found from scale 1.5" [string match "*first reduces it at scale 1.5:*" $why] $why

# --- 6. serviceability verdicts follow their limits ---------------------------------------------------
lassign [findings::serviceability [run pound m 0.3 1.0 0.04 0.01 0.0 0.049 0.0] $limits] ok word text
check "serviceability: 0.049 <= 0.05 passable" [expr {$ok == 1 && $word eq "passable"}] $text
lassign [findings::serviceability [run pound m 0.3 1.0 0.40 0.01 0.0 0.0 0.0] $limits] ok word text
check "serviceability: a peak opening of 0.40 m alone is damage to the joint, not a verdict" [expr {$ok == 1}] $text
set parts 0
foreach {label r} [list "residual transverse 0.051" [run pound m 0.3 1.0 0.04 0.01 0.0 0.0 0.051] \
                        "residual vertical step 0.051" [run pound m 0.3 1.0 0.04 0.01 0.0 0.0 0.0 0.051] \
                        "travel towards the seat's edge 1.48 > 1.475" [run pound m 0.3 1.0 0.04 0.01 0.0 0.0 0.0 0.0 1.48] \
                        "residual pier drift 0.0101 > 0.01" [run pound m 0.3 1.0 0.04 0.01 0.0 0.0 0.0 0.0 0.3 0.0101]] {
  lassign [findings::serviceability $r $limits] ok word text
  check "serviceability: $label is not passable" [expr {$ok == 0 && $word eq "not passable"}] $text
  foreach part [split $text ,] {
    if {[regexp {([0-9.]+) (<=|>) ([0-9.]+)} $part -> v op lim]} {
      incr parts
      check "serviceability: \"[string trim $part]\" is true" [expr "$v $op $lim"]
    }
  }
}
check "serviceability: five limits in each verdict" [expr {$parts == 20}] $parts
set md [findings::markdown $disagree $ladder $limits]
check "markdown: the threshold is stated" [string match "*below 5 % of the larger value*" $md]
check "markdown: one verdict line per case and motion" [expr {[regexp -all {\*\*(passable|not passable)\*\*} $md] == 6}]
check "markdown: the case without pounding is labelled the reference" [expr {[regexp -all {nopound \(reference\)} $md] == 2}]
# record pound: residual 0.08 m; not passable at 0.025 and 0.05 m, passable at 0.10 m
check "markdown: the verdicts as our limits halve and double" \
    [string match "*| record, pound | not passable | not passable | passable |*" $md] $md

if {$failures > 0} { puts "$failures checks FAILED"; exit 1 }
puts "all checks passed"
