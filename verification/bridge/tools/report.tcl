# SPDX-License-Identifier: MIT
# Report of the bridge case study: report.md with the findings against the paper (findings.tcl),
# the serviceability verdicts, a table comparing the cases, the scale ladder, PNG figures made by
# gnuplot from the CSV histories written by runCase (bridge.tcl), and screenshots of the pound
# case's viewer page. Sourced by bridge.tcl; `writeReport results outDir ?other? ?ladder?` with
# results and other lists of runCase dicts (main and second motion) and ladder a list of
# {scale case peak completed} dicts.

set reportToolsDir [file dirname [file normalize [info script]]]

proc fmt {x {digits 3}} { return [format "%.${digits}f" $x] }

# Damage state of a bearing from its peak shear strain (the bearings' design and failure limits,
# 250 % and 300 %: yoshidaBearing -limits, whose defaults they are).
proc damageWord {strain} {
  if {$strain >= 3.0} { return "failed (>300%)" }
  if {$strain >= 2.5} { return "damaged (>250%)" }
  return "sound"
}

# The serviceability limits of bridge.tcl, as findings.tcl reads them.
proc serviceLimits {} {
  return [dict create step $::serviceStep residual $::serviceResidual drift $::serviceDrift \
      seatEdge $::seatEdge seatJRA $::seatLengthJRA]
}

proc writeReport {results outDir {other {}} {ladder {}}} {
  set names {}
  foreach r $results { lappend names [dict get $r case] }
  set r0 [lindex $results 0]
  set md [open [file join $outDir report.md] w]
  puts $md "# [string map {{ bridge} { isolated bridge} { viaduct} { isolated viaduct}} [bridgeName]] under a near-fault motion\n"
  # The findings first: what a reader takes from the study.
  if {$names eq {nopound pound countermeasure}} {
    set motions [list $results]
    if {[llength $other] == 3} { lappend motions $other }
    puts $md "## The paper's findings and this model\n"
    puts $md "Zhu, Abe and Fujino (2004), three-span isolated bridge under the Takatori record, against"
    puts $md "this model under [join [lmap m $motions {findings::motionName $m}] { and }] (\"record\": [dict get $r0 motion];"
    puts $md "\"pulse\": the fitted near-fault pulse). Displacements are magnitudes of peaks over both joints or"
    puts $md "all bearings.\n"
    puts $md [findings::markdown $motions $ladder [serviceLimits]]
    if {[llength $ladder] > 0} { puts $md [ladderTable $ladder] }
    puts $md [bridgeTable]
    puts $md [whatDecides $outDir]
    puts $md "## The runs\n"
  }
  puts $md "Motion: [dict get $r0 motion], scaled by [dict get $r0 scale], at $::motionAngle degrees to the"
  puts $md "bridge axis; $::duration s analysed, integrator [dict get $r0 integrator],"
  puts $md "dt = [dict get $r0 dt] s (at most $::contactDt s while a joint is closed or closing), NormDispIncr"
  puts $md "tolerance [dict get $r0 tol] m. Model: verification/bridge/bridge.tcl"
  puts $md "(spans $::nSpans x $::spanLength m, pier heights $::pierHeights m, joint gap $::jointGap m, HDR bearings"
  puts $md "$::bearingArea m^2 x $::bearingTr m rubber per girder end in $::bearingsPerEnd bearings across the width). Gap = right"
  puts $md "girder end minus left girder end (longitudinal: + opening, - closing); bearing displacement = top"
  puts $md "minus bottom, the mean of an end's bearings (its value at the girder axis); residuals after"
  puts $md "$::tailDuration s of free vibration after the motion. A bearing past 300 % ruptures and its girder"
  puts $md "end comes down by the bearing's height ($::bearingHeight m) onto its seat.\n"

  runsTable $md $results
  if {[llength $other] > 0} {
    puts $md "\nThe same under [dict get [lindex $other 0] motion], scaled by [dict get [lindex $other 0] scale]:\n"
    runsTable $md $other
  }

  # One animated page per case, written by `recorder Viewer` (open them in a browser).
  set pages {}
  foreach n $names { if {[file exists [file join $outDir $n.html]]} { lappend pages "\[$n\]($n.html)" } }
  foreach n $names { if {[file exists [file join $outDir pulse-$n.html]]} { lappend pages "\[$n under the pulse\](pulse-$n.html)" } }
  if {[llength $pages] > 0} {
    puts $md "\n## See the bridge move\n\nViewer pages (open in a browser): [join $pages {, }]."
    set shots [viewerScreenshots $outDir pound]
    if {[llength $shots] > 0} {
      puts $md "\nThe pound case at the moment of the largest pounding force (t = [lindex $shots 0] s), true scale:\n"
      foreach {file caption} [lrange $shots 1 end] { puts $md "!\[$caption\]($file)\n" }
    } else {
      puts $md "\n(No screenshots: they need node, Chromium and the viewer's npm modules in the build.)"
    }
  }

  # Plots
  set plots [makePlots $names $outDir $results]
  if {$plots ne ""} {
    puts $md "\n## Histories\n"
    foreach {file caption} $plots { puts $md "!\[$caption\]($file)\n" }
  } else {
    puts $md "\n(gnuplot not found: no plots; the histories are in the CSV files beside this report.)"
  }
  close $md
}

# The bridge: its parameters with their sources or reasons, and its modal periods.
proc bridgeTable {} {
  set d $::derived
  set Rd [expr {0.5 * [dict get $d spanMass] * $::g}]
  set rows [list \
    [list "spans" "$::nSpans x $::spanLength m, simply supported steel girders" "ours: a typical span of the simply supported steel-girder viaducts of urban expressways (30 to 50 m); the paper does not publish its dimensions"] \
    [list "beyond the end piers" $::endCondition [dict get {adjacent "the default: the unit stands in an elevated viaduct, its end piers carry the next units' girders (rigid bodies on their bearings, their far piers elastic)" abutment "seat-type abutments with a backwall and backfill (Caltrans SDC 1.7, 7.8.1), no devices there" free "nothing: the end girders' outer ends are free (the former model)"} $::endCondition]] \
    [list "pier heights" "$::pierHeights m" "ours: unequal, so that adjacent spans differ in period, the cause of pounding"] \
    [list "pier section" "circular RC, D $::pierD m, 40 bars of 32 mm, f'c 40 MPa (core)" "ours: a level-2 ductile pier of the 1996 JRA code's time (verification/piers/pier-pushover.tcl)"] \
    [list "foundation" "footing on 3 x 3 piles of D $::pileD m, k_h $::subgradeKh kN/m3" "JRA pile-group formulas (Chang's beam on elastic foundation; axial spring a Ap Ep / L, a = 0.031 L/D - 0.15 for cast-in-place piles, JRA Part IV 2002 as we read it)"] \
    [list "girder" "$::girderMass t/m, A $::girderA m2, I $::girderIvert m4, $::girderWidth m wide, $::girderDepth m deep" "ours: steel girders, RC slab, pavement and barriers of a 10 m deck"] \
    [list "expansion joint gap" "$::jointGap m" "ours: a finger joint sized for the thermal movement of a 40 m steel span"] \
    [list "bearings" "$::bearingsPerEnd per girder end, [format %.2f [expr {$::bearingArea / $::bearingsPerEnd}]] m2 each, Tr $::bearingTr m, $::girderSpacing m apart" "ours: one high-damping rubber bearing under each main girder"] \
    [list "rubber law" "Yoshida, HDR set (a)" "fitted to Bridgestone's X0.6 design curves, Geq within 2.0 % rms, Heq 2.3 % rms (verification/bearing/fitted-parameters.md)"] \
    [list "bearing design / failure strain" "250 % / 300 %" "JRA Part V (2002): allowable shear strain under level-2 motion; failure: the paper's 300 %"] \
    [list "after rupture" "drop by $::bearingHeight m onto the lower plate, friction $::seatFriction" "the bearing's height; friction of steel on steel (ours)"] \
    [list "pounding" "$::impactLaw law, K = EA/L of the girder, e = $::restitution, mu $::frictionS / $::frictionK; 8 pairs per joint, each with 1/8 of K and of the masses" "Zhu, Abe and Fujino (2002): penalty stiffness and restitution of girder pounding (a flat impact of the joint rebounds at e: verification/bridge/joint-restitution.tcl); the other laws in the sensitivity study"] \
    [list "bearings' vertical law" [dict get {linear "linear, Kv = Ec A / Tr (Ec = 3 G (1 + 2 0.8 S^2), S 10)" kumar "Kumar et al. (2014): Kv with the offset, cavitation, buckling, P-Delta"} $::bearingVertical] "Gent's compression modulus; the other law in the sensitivity study"] \
    [list "restrainers" "two sides at +-$::deviceArm m, together K $::restrainerK kN/m, slack $::restrainerSlack m, Fy [format %.0f $::restrainerFy] kN" [format "ours; JRA Part V (2002) 16.3 designs unseating-prevention devices for 1.5 R_d = %.0f kN (R_d, a girder end's dead-load reaction, %.0f kN)" [expr {1.5 * $Rd}] $Rd]] \
    [list "bumpers" "two sides, together K $::bumperK kN/m, clearance $::bumperClearance m" "ours: rubber stoppers that close before the girders touch"] \
    [list "damping" "piers $::pierDamping, girders $::girderDamping, foundation $::foundationDamping" "stiffness-proportional Rayleigh damping (bearings, contact and devices take none)"] \
    [list "motion" "Takatori EW (RSN1120, PEER NGA-West2) at $::motionAngle deg to the axis" "the record of the paper; its NS component is not in the reference data we have (PEER distributes it to registered users; no Debian package carries it), so one component at an angle"] \
    [list "free vibration after the motion" "$::tailDuration s" "about four isolated periods, before the residuals are read"]]
  set out "## The bridge\n\n| parameter | value | source or reason |\n|---|---|---|\n"
  foreach r $rows { append out "| [join $r { | }] |\n" }
  if {[catch {modalPeriods 6} periods]} {
    append out "\n(Modal periods not computed: $periods)\n"
  } else {
    append out "\nModal periods of the bridge as built (no pounding), at the dead-load state: initial, the bearings at their tangent there; effective, every bearing's shear a linear spring of its effective stiffness at 250 % (the equivalent linear bridge of design practice).\n\n"
    append out "| mode | 1 | 2 | 3 | 4 | 5 | 6 |\n|---|---:|---:|---:|---:|---:|---:|\n"
    foreach kind {initial effective} {
      append out "| $kind (s) | [join [lmap t [dict get $periods $kind] {format %.3f $t}] { | }] |\n"
    }
  }
  return $out
}

# "What decides each finding": the stored result of the sensitivity study
# (verification/bridge/sensitivity.tcl full, about 70 runs: too long for the main job), with its
# figure copied beside the report; the section says where it comes from.
proc whatDecides {outDir} {
  set dir [file join $::reportToolsDir results]
  set file [file join $dir sensitivity.md]
  if {![file exists $file]} { return "## What decides each finding\n\n(No stored sensitivity study: run verification/bridge/sensitivity.tcl full.)\n" }
  set fh [open $file]; set text [read $fh]; close $fh
  # one level down: the study's title becomes this section's
  set text [string map {"\n## " "\n### "} $text]
  regsub {^# What decides each finding\n} $text "## What decides each finding\n\nFrom the stored sensitivity study (verification/bridge/tools/results/sensitivity.md; rerun it after changing the model):\n" text
  if {[file exists [file join $dir sensitivity.png]]} {
    file copy -force [file join $dir sensitivity.png] [file join $outDir sensitivity.png]
    append text "\n!\[What decides each finding\](sensitivity.png)\n"
  }
  return $text
}

# The table of one motion's runs, one column per case.
proc runsTable {md results} {
  set names {}
  foreach r $results { lappend names [dict get $r case] }
  set header "| quantity | unit |"
  set rule "|---|---|"
  foreach n $names { append header " $n |"; append rule "---:|" }
  puts $md $header
  puts $md $rule
  proc row {md label unit values} { puts $md "| $label | $unit | [join $values { | }] |" }
  set r0 [lindex $results 0]
  set joints [findings::jointsOf $r0]
  set girders [findings::girdersOf $r0]
  set bearings [bearingTags]
  # Up to three spans every joint, bearing and girder has its rows here; a longer viaduct gets
  # the largest values here and one table per joint and per bearing after this one.
  set every [expr {[llength $girders] <= 3}]
  if {$every} {
    foreach j $joints {
      foreach {d what} {x longitudinal y transverse z "vertical offset"} {
        set peaks {}; set residuals {}
        foreach r $results {
          lappend peaks [fmt [dict get $r peak gap$j$d]]
          lappend residuals [fmt [dict get $r last gap$j$d]]
        }
        row $md "Gap$j (PC[expr {$j + 1}]) $what, peak" m $peaks
        row $md "Gap$j (PC[expr {$j + 1}]) $what, residual" m $residuals
      }
    }
    foreach bt $bearings {
      lassign [bearingPlace $bt] p side
      set label "PC$p bearing of G[expr {$side == 11 ? $p - 1 : $p}]"
      set vals {}; set res {}; set strains {}; set states {}
      foreach r $results {
        lappend vals "[fmt [dict get $r peak bx$bt]] / [fmt [dict get $r peak by$bt]]"
        lappend res "[fmt [dict get $r last bx$bt]] / [fmt [dict get $r last by$bt]]"
        set e [dict get $r peak strain$bt]
        lappend strains "[format %.0f [expr {100 * $e}]]%"
        lappend states [damageWord $e]
      }
      row $md "$label: displacement long / trans, peak" m $vals
      row $md "$label: displacement long / trans, residual" m $res
      row $md "$label: peak shear strain (largest of its bearings)" - $strains
      row $md "$label: damage state" - $states
      set fd {}
      foreach r $results {
        set dropped [expr {[dict exists $r peak dropped$bt] ? [dict get $r peak dropped$bt] : 0}]
        lappend fd "[expr {[dict exists $r peak failed$bt] ? [dict get $r peak failed$bt] : "-"}] / $dropped"
      }
      row $md "$label: bearings failed / dropped onto the seat (of [llength [endBearings $bt]])" - $fd
    }
    foreach p [findings::piersOf $r0] {
      set v {}
      foreach r $results { lappend v "[format %.2f [expr {100 * [dict get $r peak drift$p]}]] / [format %.2f [expr {100 * [dict get $r last drift$p]}]]" }
      row $md "PC$p ([pierHeight $p] m) drift ratio, peak / residual (JRA residual limit 1.00)" % $v
    }
    foreach j $joints {
      set f {}; set n {}
      foreach r $results {
        lappend f [format %.0f [dict get $r peak force$j]]
        lappend n [lindex [dict get $r impacts] [expr {$j - 1}]]
      }
      row $md "pounding force at PC[expr {$j + 1}], peak" kN $f
      row $md "impacts at PC[expr {$j + 1}]" - $n
    }
    # the unit's end joints (endCondition adjacent or abutment)
    foreach e {0 1} where [list PC1 PC[expr {[llength $girders] + 1}]] {
      if {![dict exists $r0 peak endforce$e] || $::endCondition eq "free"} { continue }
      set other [expr {$::endCondition eq "adjacent" ? "the next unit's girder" : "the backwall"}]
      set v {}; set f {}; set res {}
      foreach r $results {
        lappend v "[fmt [dict get $r peak endopen$e]] / [fmt [expr {-[dict get $r peak endclose$e]}]]"
        lappend f "[format %.0f [dict get $r peak endforce$e]], [dict get $r peak endimpacts$e]"
        lappend res "[fmt [dict get $r last endgap$e]] / [fmt [dict get $r last endgap${e}y]] / [fmt [dict get $r last endgap${e}z]]"
      }
      row $md "end joint at $where (against $other): opening / closing, peak" m $v
      row $md "end joint at $where: pounding force peak, impacts" "kN, -" $f
      row $md "end joint at $where: residual long / trans / vertical" m $res
    }
    foreach s $girders {
      set v {}
      foreach r $results { lappend v [format %.4f [dict get $r peak rot$s]] }
      row $md "G$s rotation about the vertical, peak" rad $v
    }
    foreach s $girders {
      set v {}
      foreach r $results { lappend v [fmt [dict get $r peak g${s}x]] }
      row $md "G$s mid-span longitudinal displacement (to the ground), peak" m $v
    }
  } else {
    foreach {d what} {x longitudinal y transverse z "vertical offset"} {
      set peaks {}; set residuals {}
      foreach r $results {
        lappend peaks [fmt [findings::gapMax $r $d peak]]
        lappend residuals [fmt [findings::gapMax $r $d last]]
      }
      row $md "largest $what gap over the joints, peak (magnitude)" m $peaks
      row $md "largest $what gap over the joints, residual (magnitude)" m $residuals
    }
    set v {}; set f {}; set n {}; set st {}
    foreach r $results {
      lappend v [fmt [findings::bearingLong $r]]
      lappend st "[format %.0f [expr {100 * [findings::strainMax $r]}]]% ([findings::failedCount $r] failed)"
      set fm 0.0; set ni 0
      foreach j $joints { set fm [expr {max($fm, [dict get $r peak force$j])}] }
      foreach k [dict get $r impacts] { incr ni $k }
      lappend f [format %.0f $fm]; lappend n $ni
    }
    row $md "largest longitudinal bearing displacement, peak" m $v
    row $md "largest bearing shear strain (bearings past 300 %)" - $st
    row $md "pounding force, peak over the joints" kN $f
    row $md "impacts, all joints" - $n
    set v {}; foreach r $results { lappend v [format %.4f [findings::rotMax $r]] }
    row $md "largest girder rotation about the vertical, peak" rad $v
    set v {}
    foreach r $results { lappend v "[format %.2f [expr {100 * [findings::driftMax $r]}]] / [format %.2f [expr {100 * [findings::driftMax $r last]}]]" }
    row $md "largest pier drift ratio, peak / residual (JRA residual limit 1.00)" % $v
  }
  set mg [expr {[llength $girders] / 2 + 1}]
  set v {}; foreach r $results { lappend v "[fmt [dict get $r peak deckx]] / [fmt [dict get $r peak decky]]" }
  row $md "G$mg deck displacement X / Y (to the ground), peak" m $v
  foreach {key label unit} {wall "wall time" s} {
    set v {}; foreach r $results { lappend v [format %.1f [dict get $r $key]] }
    row $md $label $unit $v
  }
  foreach {key label} {equations "equations (free dofs after the rigid links)" steps "steps" failedSteps "failed steps (then sub-stepped)" subSteppedSteps "sub-stepped steps"
                       iterations "Newton iterations" factorizations "factorizations"} {
    set v {}; foreach r $results { lappend v [dict get $r stats $key] }
    row $md $label - $v
  }
  set v {}; foreach r $results { lappend v [dict get $r contactSubsteps] }
  row $md "of the steps, shorter contact steps (joint closed or closing)" - $v
  set v {}; foreach r $results { lappend v [dict get $r loosened] }
  row $md "steps accepted at 100x the tolerance (last resort)" - $v
  set v {}; foreach r $results { lappend v [expr {[dict get $r completed] ? "yes" : "NO"}] }
  row $md "completed" - $v
  if {!$every} { jointTables $md $results }
}

# One row per joint and one per bearing, each case's values side by side (viaducts).
proc jointTables {md results} {
  set names {}
  foreach r $results { lappend names [dict get $r case] }
  set r0 [lindex $results 0]
  puts $md "\n### Joints\n"
  puts $md "Per case: longitudinal gap peak / residual, transverse gap peak / residual, vertical offset peak (m); pounding force peak (kN), impacts.\n"
  set header "| joint |"; set rule "|---|"
  foreach n $names { append header " $n: long | trans | vert | force, impacts |"; append rule "---:|---:|---:|---:|" }
  puts $md $header; puts $md $rule
  foreach j [findings::jointsOf $r0] {
    set line "| Gap$j (PC[expr {$j + 1}]) |"
    foreach r $results {
      append line " [fmt [dict get $r peak gap${j}x]] / [fmt [dict get $r last gap${j}x]] | [fmt [dict get $r peak gap${j}y]] / [fmt [dict get $r last gap${j}y]] | [fmt [dict get $r peak gap${j}z]] | [format %.0f [dict get $r peak force$j]], [lindex [dict get $r impacts] [expr {$j - 1}]] |"
    }
    puts $md $line
  }
  puts $md "\n### Bearings\n"
  puts $md "Per case: displacement long / trans, peak (m); peak shear strain and damage state at the end.\n"
  set header "| bearing |"; set rule "|---|"
  foreach n $names { append header " $n: displacement | strain, damage |"; append rule "---:|---|" }
  puts $md $header; puts $md $rule
  foreach bt [bearingTags] {
    lassign [bearingPlace $bt] p side
    set line "| $bt: PC$p, G[expr {$side == 11 ? $p - 1 : $p}] |"
    foreach r $results {
      set e [dict get $r peak strain$bt]
      append line " [fmt [dict get $r peak bx$bt]] / [fmt [dict get $r peak by$bt]] | [format %.0f [expr {100 * $e}]]%, [damageWord $e] |"
    }
    puts $md $line
  }
}

# The scale ladder: no pounding against pounding at several scales of the record.
proc ladderTable {ladder} {
  set out "## Scale ladder\n\nThe record scaled; no pounding -> pounding. A bearing fails at 300 % shear strain.\n\n"
  append out "| scale | largest longitudinal bearing displacement | largest bearing strain, no pounding / pounding | failed bearings, no pounding / pounding | largest residual vertical step at a joint (m), no pounding / pounding | pounding force, peak (kN) |\n|---:|---|---|---|---|---:|\n"
  foreach pn [findings::ladderOf $ladder nopound] pp [findings::ladderOf $ladder pound] {
    lassign $pn s ln; lassign $pp sp lp
    if {$s != $sp} { continue }
    set rn [dict create peak [dict get $ln peak]]; set rp [dict create peak [dict get $lp peak]]
    set force 0.0
    foreach j [findings::jointsOf $lp] { set force [expr {max($force, [dict get $lp peak force$j])}] }
    set steps [lmap l [list $ln $lp] { format %.3f [findings::residualGap [dict create peak [dict get $l peak] last [dict get $l last]] z] }]
    append out "| $s | [findings::compare [findings::bearingLong $rn] [findings::bearingLong $rp] m] | [findings::pct [findings::strainMax $rn]] / [findings::pct [findings::strainMax $rp]] | [findings::failedCount $rn] / [findings::failedCount $rp] | [join $steps { / }] | [format %.0f $force] |\n"
  }
  return $out
}

# Screenshots of the case's viewer page at the frame of the largest total contact force, by the
# browser script tcl/viewer/test/screenshot.mjs (headless Chromium through the build's
# playwright-core). Returns {time file caption ...}, or {} when node, Chromium or the modules are
# missing or the script fails.
proc viewerScreenshots {outDir case} {
  set page [file join $outDir $case.html]
  set script [file normalize [file join $::reportToolsDir .. .. .. tcl viewer test screenshot.mjs]]
  set modules [file join [file dirname [info nameofexecutable]] tcl viewer npm node_modules]
  set node [auto_execok node]
  if {![file exists $page] || ![file exists $script] || $node eq "" || ![file isdirectory $modules/playwright-core]
      || ![file executable /usr/bin/chromium]} { return {} }
  if {[catch {exec env DABS_VIEWER_MODULES=$modules {*}$node $script $page $outDir viewer-$case 2>@1} out]} {
    puts "viewer screenshots failed: $out"
    return {}
  }
  if {![regexp {time ([-0-9.e+]+)} $out -> t]} { return {} }
  set shots [list $t]
  foreach {view caption} {3d "3D view" plan "plan" elevation "elevation" joint "the joint with the largest force, close up"} {
    if {[file exists [file join $outDir viewer-$case-$view.png]]} {
      lappend shots viewer-$case-$view.png "Pound case at the largest pounding force: $caption"
    }
  }
  return $shots
}

# Plots with gnuplot (pngcairo, else png). Returns {file caption ...} or "" without gnuplot.
proc makePlots {names outDir {results {}}} {
  if {[auto_execok gnuplot] eq ""} { return "" }
  set term "pngcairo size 1100,800 font ',10'"
  if {[catch {exec gnuplot -e "set terminal pngcairo" 2>@1}]} { set term "png size 1100,800" }
  set colors {nopound "#1f77b4" pound "#d62728" countermeasure "#2ca02c"}
  proc plotLines {names outDir col colors} {
    set parts {}
    foreach n $names {
      lappend parts "'[file join $outDir $n.csv]' using 1:$col with lines lw 1.2 lc rgb '[dict get $colors $n]' title '$n'"
    }
    return [join $parts ", "]
  }
  # Columns by name from the first history's header (runCase writes the same for every case): the
  # first two joints, their bearings and the first three girders (all of the three-span bridge).
  set fh [open [file join $outDir [lindex $names 0].csv]]
  set header [split [gets $fh] ,]
  close $fh
  set col [dict create]
  set i 0
  foreach name $header { dict set col $name [incr i] }
  set jointCols {}; set bearingCols {}; set forceCols {}; set girderCols {}; set rotCols {}
  set jointTitles {}; set bearingTitles {}; set forceTitles {}; set girderTitles {}
  foreach j {1 2} {
    if {![dict exists $col gap${j}x]} { continue }
    set pc PC[expr {$j + 1}]
    lappend jointCols [dict get $col gap${j}x] [dict get $col gap${j}y]
    lappend jointTitles "Gap$j longitudinal (m)" "Gap$j transverse (m)"
    foreach side {11 12} g [list $j [expr {$j + 1}]] {
      lappend bearingCols [dict get $col strain[bearingTag [expr {$j + 1}] $side]]
      lappend bearingTitles "$pc, bearing of G$g"
    }
    lappend forceCols [dict get $col force$j]
    lappend forceTitles "joint over $pc"
  }
  foreach s {1 2 3} {
    if {![dict exists $col g${s}x]} { continue }
    lappend girderCols [dict get $col g${s}x]; lappend rotCols [dict get $col rot$s]; lappend girderTitles G$s
  }
  set gp [open [file join $outDir plots.gp] w]
  puts $gp "set terminal $term"
  puts $gp "set datafile separator ','"
  puts $gp "set grid; set key top right; set xlabel 't (s)'"
  puts $gp "set output '[file join $outDir gaps.png]'"
  puts $gp "set multiplot layout 2,2 title 'Joint gaps (right girder end minus left girder end)'"
  foreach col $jointCols title $jointTitles {
    puts $gp "set title '$title'; set ylabel 'm'"
    puts $gp "plot [plotLines $names $outDir $col $colors]"
  }
  puts $gp "unset multiplot"
  puts $gp "set output '[file join $outDir bearings.png]'"
  puts $gp "set multiplot layout 2,2 title 'Bearing shear strain on [join [lsort -unique [lmap t $bearingTitles {lindex [split $t ,] 0}]] { and }] (design 250%, failure 300%)'"
  foreach col $bearingCols title $bearingTitles {
    puts $gp "set title '$title'; set ylabel 'shear strain'"
    puts $gp "plot [plotLines $names $outDir $col $colors], 2.5 with lines dt 2 lc rgb 'gray' title '250%', 3.0 with lines dt 3 lc rgb 'black' title '300%'"
  }
  puts $gp "unset multiplot"
  # The paper's figures: girder displacement histories, longitudinal and rotation about the
  # vertical, for the three cases
  puts $gp "set output '[file join $outDir girders.png]'"
  puts $gp "set multiplot layout 2,3 title 'Girder mid-span: longitudinal displacement to the ground (top) and rotation about the vertical (bottom)'"
  foreach col $girderCols title $girderTitles {
    puts $gp "set title '$title, longitudinal'; set ylabel 'm'"
    puts $gp "plot [plotLines $names $outDir $col $colors]"
  }
  foreach col $rotCols title $girderTitles {
    puts $gp "set title '$title, rotation about the vertical'; set ylabel 'rad'"
    puts $gp "plot [plotLines $names $outDir $col $colors]"
  }
  puts $gp "unset multiplot"
  # Plan view: the bearings of each girder end (one element per end stands for a pair at
  # +-bearingRollArm when bearingsPerEnd is 1) coloured by the end's worst damage state, one panel
  # per case
  if {[llength $results] > 0} {
    # true scale up to five spans; a longer viaduct is drawn wider (30 px a span) with the width of
    # the deck stretched, and its bearings unlabelled past ten spans
    set trueScale [expr {$::nSpans <= 5}]
    set labels [expr {$::nSpans <= 10}]
    set height [expr {250 * [llength $results] + 60}]
    set width [expr {max(1100, 30 * $::nSpans + 200)}]
    puts $gp "set terminal [lindex $term 0] size $width,$height [lrange $term 3 end]"
    puts $gp "set output '[file join $outDir plan.png]'"
    puts $gp "set multiplot layout [llength $results],1 title 'Plan: bearings by damage state (sound < 250 % <= past design < 300 % <= failed)'"
    set xmax [expr {$::nSpans * $::spanLength}]
    set hw [expr {0.5 * $::girderWidth}]
    set pad [expr {0.5 * sqrt($::bearingArea / max(2, $::bearingsPerEnd))}]
    set padYs [expr {$::bearingsPerEnd == 1 ? [list -$::bearingRollArm $::bearingRollArm] : [bearingYs]}]
    set obj 0
    foreach r $results {
      set objs {}
      for {set sp 1} {$sp <= $::nSpans} {incr sp} {
        set x0 [expr {[pierX $sp] + ($sp > 1 ? 0.5 * $::jointGap : 0.0)}]
        set x1 [expr {[pierX [expr {$sp + 1}]] - ($sp < $::nSpans ? 0.5 * $::jointGap : 0.0)}]
        lappend objs "set object [incr obj] rect from $x0,-$hw to $x1,$hw fc rgb '#dde3ea' fs solid border lc rgb '#8a9bb0' back"
      }
      foreach bt [findings::bearingTagsOf $r] {
        lassign [bearingPlace $bt] p side
        set x [expr {[pierX $p] + ($side == 11 ? -1.0 : 1.0) * $::bearingOffset}]
        set e [dict get $r peak strain$bt]
        set color [expr {$e >= 3.0 ? "#d62728" : ($e >= 2.5 ? "#f2c81e" : "#2ca02c")}]
        foreach y $padYs {
          lappend objs "set object [incr obj] rect from [expr {$x - $pad}],[expr {$y - $pad}] to [expr {$x + $pad}],[expr {$y + $pad}] fc rgb '$color' fs solid border lc rgb 'black' front"
        }
        # the two bearings of a pier are 2 x bearingOffset apart: left one's label to the left
        set left [expr {$side == 11}]
        if {$labels} { lappend objs "set label [incr obj] '[format %.0f [expr {100 * $e}]]%' at [expr {$x + ($left ? -0.8 : 0.8)}],[expr {$hw + 1.8}] [expr {$left ? "right" : "left"}] front" }
      }
      puts $gp "set title '[dict get $r case] (labels: peak shear strain)'; set xlabel 'x along the bridge (m)'; set ylabel 'y (m)'; set key outside right top"
      puts $gp "set xrange \[-3:[expr {$xmax + 3}]\]; set yrange \[[expr {-$hw - 3}]:[expr {$hw + 3}]\]; set size ratio [expr {$trueScale ? -1 : 0.2}]"
      puts $gp [join $objs "\n"]
      puts $gp "plot NaN notitle, NaN with boxes fc rgb '#2ca02c' fs solid title 'sound', NaN with boxes fc rgb '#f2c81e' fs solid title 'past 250 %', NaN with boxes fc rgb '#d62728' fs solid title 'failed (300 %)'"
      puts $gp "unset object; unset label"
    }
    puts $gp "unset multiplot; set size noratio; set autoscale; set xlabel 't (s)'; set key inside top right"
    puts $gp "set terminal $term"
  }
  set pn [lsearch -all -inline -not $names nopound]
  if {[llength $pn] > 0} {
    puts $gp "set output '[file join $outDir pounding.png]'"
    puts $gp "set multiplot layout 2,1 title 'Pounding force (sum over the contact pairs of a joint)'"
    foreach col $forceCols title $forceTitles {
      puts $gp "set title '$title'; set ylabel 'kN'"
      puts $gp "plot [plotLines $pn $outDir $col $colors]"
    }
    puts $gp "unset multiplot"
  }
  close $gp
  if {[catch {exec gnuplot [file join $outDir plots.gp] 2>@1} err]} {
    puts "gnuplot failed: $err"
    return ""
  }
  set out {girders.png "Girder displacement histories, longitudinal and rotation about the vertical" gaps.png "Gap1 and Gap2 histories" plan.png "Plan view: bearings by damage state" bearings.png "Bearing shear strain histories"}
  if {[llength $pn] > 0} { lappend out pounding.png "Pounding forces" }
  return $out
}
