# SPDX-License-Identifier: MIT
# What decides each of the paper's five findings: the case study (bridge.tcl, the three cases under
# the Takatori record) rerun with one parameter at a time moved to a lower and a higher value, the
# others at their defaults, and each finding judged as in the report (tools/findings.tcl) for
# every setting. Run with `ensemble` on one process or under MPI:
#
#   dabs verification/bridge/sensitivity.tcl ?study? ?outDir?
#   mpirun -n 2 --bind-to none dabs-mp verification/bridge/sensitivity.tcl full ?outDir?
#
#   study   smoke (default: two settings, 8 s of motion: the test suite's run, as ctest runs every
#           script here without arguments) | full (every parameter below at three values,
#           27 settings x 3 cases)
#   outDir  default ./sensitivity-out: sensitivity.md, sensitivity.png, the runs' results.csv
#
# The parameters, with the three values (the default in the middle, or the default and two others)
# and why they may decide a finding:
#   jointGap               0.02 0.05 0.10 m  how far the girders travel before they pound
#   endCondition           free adjacent abutment  whether the end girders pound on anything
#   bearingTr              0.15 0.20 0.25 m  rubber thickness: the isolated period and the strain
#   bearingArea            1.2 1.6 2.0 m^2   rubber area per girder end: the same, the other way
#   pierContrast           0 1 2        pier heights moved towards (0: all at the mean) or away (2)
#                                       from their mean: the difference of the spans' periods
#   restrainerSlack        0.02 0.05 0.10 m   when the cables start to pull
#   restrainerK            2e4 4e4 8e4 kN/m   how hard they pull
#   impactStiffnessFactor  0.1 1 10     the contact's penalty stiffness against EA/L
#   restitution            0.4 0.65 0.9 how much energy an impact takes
#   impactLaw              kelvin hertz hertzdamp jankowski   the contact's force law (kelvin the
#                                       paper's; the power laws' k_h as bridge.tcl sets it)
#   bearingVertical        linear kumar the bearings' vertical law (kumar: Kv falling with the
#                                       offset, cavitation, buckling, P-Delta)
#   motionAngle            0 30 60 deg  the motion's direction against the bridge axis
#   scale                  1.0 1.5 2.0  the record's amplitude
# A finding "flips" with a parameter when its verdict at any other value differs from the
# verdict at the defaults. The countermeasure is designed for its joint, so with the gap its
# longitudinal devices follow it as at the defaults: the restrainers' slack equal to the gap (0.05
# m at 0.05 m) and the bumpers' clearance 0.6 times it (0.03 m), so that the bumpers still close
# before the girders touch at a 0.02 m gap (the transverse devices' 0.05 m stays). The
# serviceability limits follow the joint too: the residual offset a joint accommodates is its
# gap, and the seat's travel is half the cap less half the gap.

set here [file dirname [file normalize [info script]]]
set ::bridgeLibraryOnly 1
source [file join $here bridge.tcl]
source [file join $here tools findings.tcl]
source [file join $here .. ensemble results.tcl]

set study [expr {$argc > 0 ? [lindex $argv 0] : "smoke"}]
set outDir [file normalize [expr {$argc > 1 ? [lindex $argv 1] : "sensitivity-out"}]]
if {$study ni {smoke full}} { error "study must be full or smoke, got \"$study\"" }

set parameters {
  jointGap {0.02 0.05 0.10}
  endCondition {free adjacent abutment}
  bearingTr {0.15 0.20 0.25}
  bearingArea {1.2 1.6 2.0}
  pierContrast {0 1 2}
  restrainerSlack {0.02 0.05 0.10}
  restrainerK {2e4 4e4 8e4}
  impactStiffnessFactor {0.1 1 10}
  restitution {0.4 0.65 0.9}
  impactLaw {kelvin hertz hertzdamp jankowski}
  bearingVertical {linear kumar}
  motionAngle {0 30 60}
  scale {1.0 1.5 2.0}
}
set studyDuration $duration
if {$study eq "smoke"} {
  set parameters {jointGap {0.05 0.10}}
  set studyDuration 8.0
}
# The defaults, as bridge.tcl sets them (pierContrast 1 is the pier heights as they are, scale 1
# the record as recorded); every job starts from them.
set defaults [dict create pierContrast 1 scale 1.0]
foreach {name values} $parameters {
  if {$name ni {pierContrast scale}} { dict set defaults $name [set $name] }
}
set defaultHeights $pierHeights
dict set defaults pierHeights $defaultHeights
dict set defaults bumperClearance $bumperClearance

# One job per setting: the defaults, then each parameter at each of its values that is not its
# default (a value equal to the default is the defaults' job).
set jobs [list [list id defaults parameter none value -]]
foreach {name values} $parameters {
  foreach v $values {
    if {$v == [dict get $defaults $name] || $v eq [dict get $defaults $name]} { continue }
    lappend jobs [list id "${name}_$v" parameter $name value $v]
  }
}

# The three cases of one setting and the five findings judged on them.
proc sensitivityRun {job} {
  dict with job {}
  dict for {name v} $::defaults { set ::$name $v }
  set scale 1.0
  set ::duration $::studyDuration
  switch -- $parameter {
    none {}
    scale { set scale $value }
    pierContrast {
      set mean [expr {[tcl::mathop::+ {*}$::defaultHeights] / [llength $::defaultHeights]}]
      set ::pierHeights [lmap h $::defaultHeights { expr {$mean + $value * ($h - $mean)} }]
    }
    jointGap {
      set ::jointGap $value
      set ::restrainerSlack [expr {$value * $::restrainerSlack / [dict get $::defaults jointGap]}]
      set ::bumperClearance [expr {$value * $::bumperClearance / [dict get $::defaults jointGap]}]
    }
    default { set ::$parameter $value }
  }
  set limits [dict create step $::serviceStep residual $::jointGap drift $::serviceDrift \
      seatEdge [expr {0.5 * [lindex $::capSize 0] - 0.5 * $::jointGap}] seatJRA $::seatLengthJRA]
  set runs {}
  set wall 0.0
  foreach c {nopound pound countermeasure} {
    set r [runCase $c $scale $::defaultDt $::defaultIntegrator $::defaultTol record]
    if {![dict get $r completed]} { return [list code -1] }
    set wall [expr {$wall + [dict get $r wall]}]
    lappend runs $r
  }
  set rows [findings::paperFindings [list $runs] {} $limits]
  set out [list code 0]
  foreach row $rows { lappend out agree[dict get $row n] [expr {[dict get $row verdict] eq "agrees"}] }
  lassign $runs rn rp rc
  lappend out midLongNopound [findings::midBearingLong $rn] midLongPound [findings::midBearingLong $rp] \
      midGapPound [findings::midGapMax $rp x] midGapCounter [findings::midGapMax $rc x] \
      midRotPound [findings::midRot $rp] midRotCounter [findings::midRot $rc] \
      transPound [findings::gapMax $rp y] transCounter [findings::gapMax $rc y] \
      failed [tcl::mathfunc::max {*}[lmap r $runs {findings::failedCount $r}]] \
      step [tcl::mathfunc::max {*}[lmap r $runs {findings::residualGap $r z}]] \
      wall [format %.2f $wall]
  return $out
}

# The smoke study starts from an empty folder (a rerun must run the model as it is now).
if {$study eq "smoke" && [getPID] == 0} { file delete -force [file join $outDir runs] }
set t0 [clock milliseconds]
set summary [ensemble run $jobs sensitivityRun -out [file join $outDir runs]]
set wall [expr {([clock milliseconds] - $t0) / 1000.0}]
if {[getPID] != 0} { return }
puts [format "%s sensitivity study: %d settings on %d process(es), %.1f s: %s" $study [llength $jobs] [getNP] $wall $summary]

# ---------------------------------------------------------------------------------------------
# What decides each finding
# ---------------------------------------------------------------------------------------------
set byId [dict create]
foreach row [ensembleResults::read [dict get $summary file]] { dict set byId [dict get $row id] $row }
set statements {
  1 "Pounding greatly reduces the longitudinal displacement (middle span)"
  2 "The countermeasure works longitudinally and in rotation (middle span)"
  3 "Peak and residual longitudinal gaps do not harm serviceability"
  4 "The countermeasure reduces the peak transverse gap"
  5 "Rubber bearings fail (300 %) and leave unevenness"
}
# Verdict of finding n in the job id: 1 agrees, 0 differs, "" when the run failed.
proc verdictOf {id n} {
  set row [dict get $::byId $id]
  if {[dict get $row status] ne "ok"} { return "" }
  return [dict get $row agree$n]
}
proc word {v} { return [expr {$v eq "" ? "failed" : ($v ? "agrees" : "differs")}] }
proc idOf {name v} {
  if {$v == [dict get $::defaults $name] || $v eq [dict get $::defaults $name]} { return defaults }
  return "${name}_$v"
}

set md [open [file join $outDir sensitivity.md] w]
puts $md "# What decides each finding\n"
puts $md [format "Sensitivity study of the case study (%s): the three cases under the Takatori record for %d settings, one parameter at a time at its other values with the others at their defaults; %d runs, of which this call ran %d settings on %d process(es) in %.0f s%s. Command: \`dabs verification/bridge/sensitivity.tcl %s\` (or under \`mpirun -n 2 --bind-to none dabs-mp\`). Each finding judged as in the report (verification/bridge/tools/findings.tcl); a finding flips with a parameter when its verdict at another value differs from the one at the defaults.\n" \
    $study [llength $jobs] [expr {3 * [llength $jobs]}] [dict get $summary ran] [getNP] $wall \
    [expr {[dict get $summary ran] < [llength $jobs] ? " (the others' results were already in the output folder)" : ""}] $study]
foreach {n text} $statements {
  set d [verdictOf defaults $n]
  puts $md "## $n. $text\n"
  puts $md "At the defaults: **[word $d]**.\n"
  set flips {}
  set table "| parameter | values |\n|---|---|\n"
  foreach {name values} $parameters {
    set cells {}
    set flipped {}
    foreach v $values {
      set w [verdictOf [idOf $name $v] $n]
      lappend cells "$v: [word $w]"
      if {$w ne "" && $d ne "" && $w != $d} { lappend flipped $v }
    }
    append table "| $name | [join $cells {; }] |\n"
    if {[llength $flipped] > 0} { lappend flips "$name at [join $flipped { and }]" }
  }
  if {[llength $flips] == 0} {
    puts $md "No parameter of the study flips it within these ranges.\n"
  } else {
    puts $md "It flips with [join $flips {; }].\n"
  }
  puts $md $table
}
# Numbers behind the verdicts: one row per setting.
puts $md "## The numbers of each setting\n"
puts $md "| setting | G2 bearing displacement, nopound / pound (m) | G2 joints' peak gap, pound / countermeasure (m) | G2 rotation, pound / countermeasure (rad) | peak transverse gap, pound / countermeasure (m) | failed bearings (most of the cases) | residual vertical step (m) | wall (s) |"
puts $md "|---|---|---|---|---|---|---|---|"
foreach job $jobs {
  set row [dict get $byId [dict get $job id]]
  if {[dict get $row status] ne "ok"} { puts $md "| [dict get $job id] | run failed ||||||| "; continue }
  puts $md [format "| %s | %.3f / %.3f | %.3f / %.3f | %.4f / %.4f | %.3f / %.3f | %d | %.3f | %s |" [dict get $job id] \
      [dict get $row midLongNopound] [dict get $row midLongPound] [dict get $row midGapPound] [dict get $row midGapCounter] \
      [dict get $row midRotPound] [dict get $row midRotCounter] [dict get $row transPound] [dict get $row transCounter] \
      [dict get $row failed] [dict get $row step] [dict get $row wall]]
}
close $md

# The figure: per finding, a grid of the parameters (rows) against their values in the order of
# the table (columns, each cell labelled with its value), green where the finding agrees with
# the paper, red where it differs.
set dat [file join $outDir sensitivity.dat]
set fh [open $dat w]
set names [dict keys $parameters]
foreach {n text} $statements {
  set i 0
  foreach {name values} $parameters {
    set k 0
    foreach v $values {
      set w [verdictOf [idOf $name $v] $n]
      puts $fh "$k $i [expr {$w eq "" ? 0.5 : $w}] $v"
      incr k
    }
    incr i
  }
  puts $fh "\n"
}
close $fh
if {[auto_execok gnuplot] ne ""} {
  set ytics [join [lmap name $names {format "'%s' %d" $name [lsearch $names $name]}] ", "]
  set gp "set terminal pngcairo size 1800,700 font ',10'\nset output '[file join $outDir sensitivity.png]'\n"
  append gp "set multiplot layout 1,5 title 'What decides each finding: green agrees with the paper, red differs (one parameter at a time, each cell labelled with its value)'\n"
  append gp "set palette defined (0 '#d62728', 0.5 '#bbbbbb', 1 '#2ca02c')\nset cbrange \[0:1\]\nunset colorbox\n"
  append gp "set xrange \[-0.5:3.5\]\nset yrange \[-0.5:[expr {[llength $names] - 0.5}]\]\nunset xtics\nset ytics ($ytics)\n"
  set block 0
  foreach {n text} $statements {
    append gp "set title 'finding $n'\nplot '$dat' index $block using 1:2:(0.48):(0.48):3 with boxxyerror fs solid lc palette notitle, '' index $block using 1:2:4 with labels font ',8' notitle\n"
    incr block
  }
  append gp "unset multiplot\n"
  if {[catch {exec gnuplot << $gp} err]} { puts "gnuplot: $err" }
}
puts "sensitivity: [file join $outDir sensitivity.md]"

# The smoke study checks itself (the test suite runs it): every setting completed, and each
# finding's verdict written for each setting, as the report's findings judge it.
if {$study eq "smoke"} {
  source [file join $here .. lib check.tcl]
  checkTrue "every setting of the smoke study completed ($summary)" [expr {[dict get $summary ok] == [llength $jobs]}]
  foreach job $jobs {
    foreach {n text} $statements {
      checkTrue "[dict get $job id]: finding $n judged" [expr {[verdictOf [dict get $job id] $n] in {0 1}}]
    }
  }
  finish
}
