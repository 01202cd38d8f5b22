# SPDX-License-Identifier: MIT
# Report of the bridge case study (issue 6): report.md with one table comparing the cases and PNG
# plots made by gnuplot from the CSV histories written by runCase (bridge.tcl). Sourced by
# bridge.tcl; `writeReport results outDir` with results a list of runCase dicts.

proc fmt {x {digits 3}} { return [format "%.${digits}f" $x] }

# Damage state of a bearing from its peak shear strain (limits of the issue: 250 % and 300 %).
proc damageWord {strain} {
  if {$strain >= 3.0} { return "failed (>300%)" }
  if {$strain >= 2.5} { return "damaged (>250%)" }
  return "sound"
}

proc writeReport {results outDir} {
  set names {}
  foreach r $results { lappend names [dict get $r case] }
  set r0 [lindex $results 0]
  set md [open [file join $outDir report.md] w]
  puts $md "# Three-span isolated bridge under a near-fault motion\n"
  puts $md "Motion: [dict get $r0 motion], scaled by [dict get $r0 scale], at $::motionAngle degrees to the"
  puts $md "bridge axis; $::duration s analysed, integrator [dict get $r0 integrator],"
  puts $md "dt = [dict get $r0 dt] s (at most $::contactDt s while a joint is closed or closing), NormDispIncr"
  puts $md "tolerance [dict get $r0 tol] m. Model: verification/bridge/bridge.tcl"
  puts $md "(spans $::nSpans x $::spanLength m, pier heights $::pierHeights m, joint gap $::jointGap m, HDR bearings"
  puts $md "$::bearingArea m^2 x $::bearingTr m rubber per girder end). Gap = right girder end minus left girder end"
  puts $md "(longitudinal: + opening, - closing); bearing displacement = top minus bottom.\n"

  set header "| quantity | unit |"
  set rule "|---|---|"
  foreach n $names { append header " $n |"; append rule "---:|" }
  puts $md $header
  puts $md $rule
  proc row {md label unit values} { puts $md "| $label | $unit | [join $values { | }] |" }
  foreach {key label} {gap1x "Gap1 (PC2) longitudinal" gap1y "Gap1 (PC2) transverse"
                       gap2x "Gap2 (PC3) longitudinal" gap2y "Gap2 (PC3) transverse"} {
    set peaks {}; set residuals {}
    foreach r $results {
      lappend peaks [fmt [dict get $r peak $key]]
      lappend residuals [fmt [dict get $r last $key]]
    }
    row $md "$label, peak" m $peaks
    row $md "$label, residual" m $residuals
  }
  foreach {bt label} {2011 "PC2 bearing of G1" 2012 "PC2 bearing of G2" 3011 "PC3 bearing of G2" 3012 "PC3 bearing of G3"} {
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
    row $md "$label: peak shear strain" - $strains
    row $md "$label: damage state" - $states
  }
  foreach j {1 2} pc {PC2 PC3} {
    set f {}; set n {}
    foreach r $results {
      lappend f [format %.0f [dict get $r peak force$j]]
      lappend n [lindex [dict get $r impacts] [expr {$j - 1}]]
    }
    row $md "pounding force at $pc, peak" kN $f
    row $md "impacts at $pc" - $n
  }
  foreach s {1 2 3} {
    set v {}
    foreach r $results { lappend v [format %.4f [dict get $r peak rot$s]] }
    row $md "G$s rotation about the vertical, peak" rad $v
  }
  set v {}; foreach r $results { lappend v "[fmt [dict get $r peak deckx]] / [fmt [dict get $r peak decky]]" }
  row $md "G2 deck displacement X / Y (to the ground), peak" m $v
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

  # Findings of the paper, checked on these numbers.
  if {[llength $names] == 3} {
    lassign $results rn rp rc
    puts $md "\n## Findings\n"
    set bn 0.0; set bp 0.0
    foreach bt {2011 2012 3011 3012} {
      set bn [expr {max($bn, abs([dict get $rn peak bx$bt]))}]
      set bp [expr {max($bp, abs([dict get $rp peak bx$bt]))}]
    }
    puts $md "- Pounding and longitudinal displacement: the largest longitudinal bearing displacement at the"
    puts $md "  joints (PC2, PC3) is [fmt $bn] m without pounding and [fmt $bp] m with pounding"
    puts $md "  ([expr {$bp < $bn ? "reduced, as in the paper" : "not reduced: see the discussion in README"}])."
    set tp [expr {max(abs([dict get $rp peak gap1y]), abs([dict get $rp peak gap2y]))}]
    set tc [expr {max(abs([dict get $rc peak gap1y]), abs([dict get $rc peak gap2y]))}]
    puts $md "- Countermeasure and transverse gap: the largest transverse gap is [fmt $tp] m with pounding"
    puts $md "  alone and [fmt $tc] m with restrainers and bumpers"
    puts $md "  ([expr {$tc < $tp ? "reduced, as in the paper" : "not reduced"}])."
  }

  # One animated page per case, written by `recorder Viewer` (open them in a browser).
  set pages {}
  foreach n $names { if {[file exists [file join $outDir $n.html]]} { lappend pages "\[$n\]($n.html)" } }
  if {[llength $pages] > 0} { puts $md "\n## See the bridge move\n\n[join $pages {, }]" }

  # Plots
  set plots [makePlots $names $outDir]
  if {$plots ne ""} {
    puts $md "\n## Histories\n"
    foreach {file caption} $plots { puts $md "!\[$caption\]($file)\n" }
  } else {
    puts $md "\n(gnuplot not found: no plots; the histories are in the CSV files beside this report.)"
  }
  close $md
}

# Plots with gnuplot (pngcairo, else png). Returns {file caption ...} or "" without gnuplot.
proc makePlots {names outDir} {
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
  set gp [open [file join $outDir plots.gp] w]
  puts $gp "set terminal $term"
  puts $gp "set datafile separator ','"
  puts $gp "set grid; set key top right; set xlabel 't (s)'"
  puts $gp "set output '[file join $outDir gaps.png]'"
  puts $gp "set multiplot layout 2,2 title 'Joint gaps (right girder end minus left girder end)'"
  foreach col {2 3 4 5} title {"Gap1 longitudinal (m)" "Gap1 transverse (m)" "Gap2 longitudinal (m)" "Gap2 transverse (m)"} {
    puts $gp "set title '$title'; set ylabel 'm'"
    puts $gp "plot [plotLines $names $outDir $col $colors]"
  }
  puts $gp "unset multiplot"
  puts $gp "set output '[file join $outDir bearings.png]'"
  puts $gp "set multiplot layout 2,2 title 'Bearing shear strain on PC2 and PC3 (design 250%, failure 300%)'"
  foreach col {6 7 8 9} title {"PC2, bearing of G1" "PC2, bearing of G2" "PC3, bearing of G2" "PC3, bearing of G3"} {
    puts $gp "set title '$title'; set ylabel 'shear strain'"
    puts $gp "plot [plotLines $names $outDir $col $colors], 2.5 with lines dt 2 lc rgb 'gray' title '250%', 3.0 with lines dt 3 lc rgb 'black' title '300%'"
  }
  puts $gp "unset multiplot"
  set pn [lsearch -all -inline -not $names nopound]
  if {[llength $pn] > 0} {
    puts $gp "set output '[file join $outDir pounding.png]'"
    puts $gp "set multiplot layout 2,1 title 'Pounding force (sum over the contact pairs of a joint)'"
    foreach col {14 15} title {"joint over PC2" "joint over PC3"} {
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
  set out {gaps.png "Gap histories" bearings.png "Bearing shear strain histories"}
  if {[llength $pn] > 0} { lappend out pounding.png "Pounding forces" }
  return $out
}
