# SPDX-License-Identifier: MIT
# Fragility of the three-span bridge (bridge.tcl) from an ensemble of runs: the three cases
# (nopound, pound, countermeasure) under every ground-motion record and a family of near-fault
# pulses, each scaled to a ladder of peak ground velocities (incremental dynamic analysis,
# Vamvatsikos and Cornell 2002), then lognormal fragility curves of the damage states below against
# PGV and against Sa(T_iso), fitted by maximum likelihood and by the IDA method with bootstrap
# bands (verification/ensemble/fragility.tcl).
#
#   dabs verification/bridge/ensemble.tcl ?study? ?outDir?
#   mpirun -n 4 dabs-mp verification/bridge/ensemble.tcl full ensemble-out      (or srun ...)
#
#   study   smoke (default: 8 short runs, what the test suite runs) | full (the study)
#   outDir  default ./ensemble-out: runs/jobs/<id>.csv (one per run), runs/results.csv (all runs),
#           fragility.csv, fragility.md (tables and the answer), fragility-pgv.png, fragility-sa.png
# A rerun skips the runs already done (killed studies resume).
#
# Motions
#   records  every .AT2 file in verification/data (Takatori EW, El Centro NS, Northridge Arleta
#            360: copies of the measured records, headers kept)
#   pulses   the Mavroeidis-Papageorgiou pulse (timeSeries NearFaultPulse) with periods Tp from
#            0.5 to 4 s, inside the 0.4-12.9 s of the 91 pulse-like NGA records Baker (2007, BSSA
#            97(5):1486-1501) found and around the isolated periods; gamma and nu as fitted to
#            Takatori in bridge.tcl. A pulse's velocity amplitude and a scale factor are the same
#            thing (the series is linear in Vp), so the velocities are the PGV ladder below.
#   ladder   each motion scaled to PGV = 0.3 ... 2.0 m/s: from Baker's 0.3 m/s threshold of a
#            pulse-like record to above the largest PGVs recorded near faults (Takatori EW 1.23
#            m/s as distributed)
# Damage states (the limits and their source; the serviceability limits of bridge.tcl's report)
#   bearing-250  a bearing's peak shear strain >= 250 %: the allowable shear strain of rubber
#                bearings under level-2 ground motion (Japan Road Association, Specifications for
#                Highway Bridges, Part V, 2002), the design limit of bridge.tcl's report
#   bearing-300  >= 300 %: bearing failure (the failure strain of bridge.tcl's report)
#   joint        peak longitudinal opening of a joint > its gap: damage to the expansion joint's
#                fingers (ours: the joint accommodates +- its gap); the unit's end joints, against
#                the next unit or the backwall, count as joints here, in residual and in step
#   unseating    a girder end's travel towards the edge of its seat > its seat (bridge.tcl seatEdge:
#                half the cap length less half the gap; JRA's minimum S_EM = 0.7 + 0.005 L is 0.9 m)
#   residual     residual longitudinal or transverse offset of a joint > the gap (ours)
#   step         residual vertical step at a joint > 0.05 m (ours: ruptured bearings let girders down)
#   drift        residual pier drift ratio > 1/100 (JRA Part V, 1996 and 2002)
#   service-lost the bridge cannot carry traffic: unseating, residual, step or drift (the report's
#                verdict; the peak opening is damage to the joint, not part of it)
# and the HAZUS-MH bridge damage states (FEMA, HAZUS-MH MR4 Technical Manual, chapter 7), each
# mapped by us to these quantities from its description (paraphrased here; a state is also
# exceeded when a higher one is; the column criteria of HAZUS are not mapped):
#   slight       minor cracking and spalling at hinges, minor cracking of the deck: joint, or
#                bearing-250
#   moderate     keeper-bar or rocker-bearing failure without unseating, moderate movement:
#                bearing-300, or residual
#   extensive    significant residual movement at connections, vertical offset, differential
#                settlement at connections: step, or drift
#   complete     a connection losing all bearing support, imminent deck collapse: unseating
# Modelling uncertainty (full study): each motion runs on its own realisation of the bridge, the
# same at every level of its ladder (Nielson and DesRoches 2007 sample one bridge per motion),
# drawn with a fixed seed: joint gap uniform 0.03 to 0.07 m (ours: the gap at installation
# depends on the temperature then); the rubber's force (Y0: stiffness and strength together)
# lognormal with median 1 and dispersion 0.1 (ours: production bearings scatter by about 10 % in
# shear stiffness); contact friction mu_k uniform 0.3 to 0.5 with mu_s = mu_k + 0.1 (ours, about
# the default 0.4 / 0.5); restitution uniform 0.5 to 0.8 (ours, about Zhu et al.'s 0.65); the
# rubber's equivalent damping ratio Heq at the design strain lognormal with median 1 and
# dispersion 0.1 apart from its force (ours, as for the force; bridge.tcl's hdrScaled moves the
# set's yield deformation, verification/bridge/bearing-scatter.tcl checks it). The devices follow
# the sampled gap as in the sensitivity study: the restrainers' slack and the bumpers' clearance
# keep their ratios to the gap (1 and 0.6), so that a narrow gap does not leave slack cables and a
# wide one bumpers that close long before the girders would touch.
# Fits, against PGV and Sa(T_iso): the maximum-likelihood fit of every run (Baker 2015, eq. 11),
# and the incremental-dynamic-analysis fit (Baker 2015, eqs. 3 and 4: the PGV at which each motion
# first exceeds the state; motions that never do are counted and left out) with bootstrap 90 %
# bands of the median (verification/ensemble/fragility.tcl).
# A run whose analysis fails (a step that no algorithm brings to convergence) is recorded as failed
# and left out of the fits; the tables count them.

set here [file dirname [file normalize [info script]]]
set ::bridgeLibraryOnly 1
source [file join $here bridge.tcl]
source [file join $here .. ensemble fragility.tcl]
source [file join $here .. ensemble intensity.tcl]
source [file join $here tools findings.tcl]
source [file join $here .. ensemble results.tcl]

set study [expr {$argc > 0 ? [lindex $argv 0] : "smoke"}]
set outDir [file normalize [expr {$argc > 1 ? [lindex $argv 1] : "ensemble-out"}]]
if {$study ni {smoke full}} { error "study must be smoke or full, got \"$study\"" }

# ---------------------------------------------------------------------------------------------
# The study
# ---------------------------------------------------------------------------------------------
set cases {nopound pound countermeasure}
set pulsePeriods {0.5 0.75 1.0 1.5 2.0 3.0 4.0}  ;# s
set pgvLadder {0.3 0.5 0.75 1.0 1.25 1.5 1.75 2.0} ;# m/s
set studyDuration $duration                        ;# s of each analysis (bridge.tcl: 20 s)
set recordFolders [list [file join $here .. data]]
set recordPatterns {*.AT2 *.at2}
if {$study eq "smoke"} {
  set cases {pound countermeasure}
  set pulsePeriods {1.0}
  set pgvLadder {0.5 1.5}
  set studyDuration 8.0
  set recordFolders [list [file join $here .. data]]
  set recordPatterns {elCentro.at2}
}
set limits [dict create bearing-250 2.5 bearing-300 3.0 joint $jointGap unseating $seatEdge \
    residual $serviceResidual step $serviceStep drift $serviceDrift]
set damageStates {bearing-250 bearing-300 joint unseating residual step drift service-lost \
    hazus-slight hazus-moderate hazus-extensive hazus-complete}
# The realisation of the bridge each motion runs on (modelling uncertainty; the full study only):
# a linear congruential generator with a fixed seed, in the order of the motions.
proc uniform {state lo hi} {
  upvar 1 $state x
  set x [expr {(1664525 * $x + 1013904223) % 4294967296}]
  return [expr {$lo + ($hi - $lo) * $x / 4294967296.0}]
}
proc standardNormal {state} {
  upvar 1 $state x
  # Box-Muller from two uniforms in (0, 1]
  set u1 [expr {1.0 - [uniform x 0.0 1.0]}]
  set u2 [uniform x 0.0 1.0]
  return [expr {sqrt(-2.0 * log($u1)) * cos(2.0 * acos(-1.0) * $u2)}]
}
set sampleModels [expr {$study eq "full"}]

# Isolated period: one span's deck on its bearings at their effective stiffness Keq at the design
# strain, 250 % (bridge.tcl's estimate).
buildModel pound
set Tiso [dict get $::derived Tiso]
wipe

# Motions and their intensity at scale 1, computed by every process (the job list must be the
# same everywhere; `ensemble run` uses process 0's).
set motions [dict create]
set seen {}
foreach folder $recordFolders {
  foreach file [lsort [glob -nocomplain -directory $folder {*}$recordPatterns]] {
    set key [string tolower [file tail $file]]
    if {$key in $seen} { continue }
    lappend seen $key
    set h [intensity::recordHeader $file]
    set im [intensity::measures [list timeSeries Path 1 -filePath $file -factor $g] $Tiso 0.05 \
        [expr {[dict get $h npts] * [dict get $h dt]}] [dict get $h dt]]
    dict set motions [file rootname [file tail $file]] [dict create kind record file $file \
        pgv [dict get $im pgv] sa [expr {[dict get $im sa] / $g}]]
  }
}
foreach Tp $pulsePeriods {
  set t0 [expr {max(3.0, 0.5 * $pulseGamma * $Tp + 1.0)}]
  set series [list timeSeries NearFaultPulse 1 -Tp $Tp -Vp 1.0 -gamma $pulseGamma -nu $pulseNu -t0 $t0]
  set im [intensity::measures $series $Tiso 0.05 $studyDuration 0.002]
  dict set motions [format "pulse-Tp%.2f" $Tp] [dict create kind pulse Tp $Tp t0 $t0 \
      pgv [dict get $im pgv] sa [expr {[dict get $im sa] / $g}]]
}

set realisations [dict create]
set rng 20261127
dict for {name m} $motions {
  if {$sampleModels} {
    set muK [uniform rng 0.3 0.5]
    dict set realisations $name [dict create jointGap [uniform rng 0.03 0.07] \
        rubberFactor [expr {exp(0.1 * [standardNormal rng])}] frictionK $muK frictionS [expr {$muK + 0.1}] \
        restitution [uniform rng 0.5 0.8] dampingFactor [expr {exp(0.1 * [standardNormal rng])}]]
  } else {
    dict set realisations $name [dict create jointGap $jointGap rubberFactor 1.0 frictionK $frictionK \
        frictionS $frictionS restitution $restitution dampingFactor 1.0]
  }
}
set defaultHdr $hdr
set defaultDevices [dict create jointGap $jointGap restrainerSlack $restrainerSlack bumperClearance $bumperClearance]

# One job per case, motion and PGV level; the strongest first, so that the long runs start early
# and the short ones fill the end (the farm hands jobs out in this order).
set jobs {}
foreach level [lsort -real -decreasing $pgvLadder] {
  foreach c $cases {
    dict for {name m} $motions {
      set scale [expr {$level / [dict get $m pgv]}]
      lappend jobs [list id [format "%s-%s-pgv%.2f" $c $name $level] case $c motion $name \
          level $level scale [format %.6g $scale]]
    }
  }
}

# One run: the bridge under the motion scaled, its intensity and its peak responses.
proc bridgeRun {job} {
  dict with job {}
  set m [dict get $::motions $motion]
  set ::duration $::studyDuration
  # this motion's realisation of the bridge
  set real [dict get $::realisations $motion]
  foreach key {jointGap frictionK frictionS restitution} { set ::$key [dict get $real $key] }
  foreach key {restrainerSlack bumperClearance} {
    set ::$key [expr {[dict get $::defaultDevices $key] * $::jointGap / [dict get $::defaultDevices jointGap]}]
  }
  # the bearings' scatter (their own small model: before runCase builds the bridge)
  set ::hdr [hdrScaled $::defaultHdr [dict get $real rubberFactor] [dict get $real dampingFactor] $::bearingDesignStrain]
  if {[dict get $m kind] eq "pulse"} {
    set ::pulseTp [dict get $m Tp]; set ::pulseVp 1.0; set ::pulseT0 [dict get $m t0]
    set input pulse
  } else {
    set input [dict get $m file]
  }
  set r [runCase $case $scale $::defaultDt $::defaultIntegrator $::defaultTol $input]
  set ::hdr $::defaultHdr
  dict for {key value} $::defaultDevices { set ::$key $value }
  # the quantities of the damage states, as the report reads them (tools/findings.tcl), over the
  # joints and the unit's end joints
  set residual [expr {max([findings::residualOpening $r], [findings::residualGap $r y])}]
  return [list code [expr {[dict get $r completed] ? 0 : -1}] \
      pgv [expr {$scale * [dict get $m pgv]}] sa [expr {$scale * [dict get $m sa]}] \
      strain [findings::strainMax $r] opening [findings::openingMax $r] residual $residual \
      step [findings::residualGap $r z] seat [findings::seatTravel $r] drift [findings::driftMax $r last] \
      gap [dict get $real jointGap] wall [format %.3f [dict get $r wall]]]
}

# The smoke study starts from an empty folder: its runs are short, and a rerun of the test suite
# must run the model as it is now, not skip runs of an earlier model with the same parameters.
if {$study eq "smoke" && [getPID] == 0} { file delete -force [file join $outDir runs] }
set t0 [clock milliseconds]
set summary [ensemble run $jobs bridgeRun -out [file join $outDir runs]]
set wall [expr {([clock milliseconds] - $t0) / 1000.0}]
if {[getPID] != 0} { return }
puts [format "%s study: %d runs on %d process(es), %.1f s: %s" $study [llength $jobs] [getNP] $wall $summary]

# ---------------------------------------------------------------------------------------------
# Fragility
# ---------------------------------------------------------------------------------------------
proc exceeds {row ds} {
  set lim $::limits
  switch -- $ds {
    bearing-250 { return [expr {[dict get $row strain] >= [dict get $lim bearing-250]}] }
    bearing-300 { return [expr {[dict get $row strain] >= [dict get $lim bearing-300]}] }
    joint { return [expr {[dict get $row opening] > [dict get $row gap]}] }
    unseating { return [expr {[dict get $row seat] > 0.5 * [lindex $::capSize 0] - 0.5 * [dict get $row gap]}] }
    residual { return [expr {[dict get $row residual] > [dict get $row gap]}] }
    step { return [expr {[dict get $row step] > [dict get $lim step]}] }
    drift { return [expr {[dict get $row drift] > [dict get $lim drift]}] }
    service-lost {
      return [expr {[exceeds $row unseating] || [exceeds $row residual] || [exceeds $row step] || [exceeds $row drift]}]
    }
    hazus-complete { return [exceeds $row unseating] }
    hazus-extensive { return [expr {[exceeds $row step] || [exceeds $row drift] || [exceeds $row hazus-complete]}] }
    hazus-moderate { return [expr {[exceeds $row bearing-300] || [exceeds $row residual] || [exceeds $row hazus-extensive]}] }
    hazus-slight { return [expr {[exceeds $row joint] || [exceeds $row bearing-250] || [exceeds $row hazus-moderate]}] }
  }
}

set rows [ensembleResults::read [dict get $summary file]]
set fits [dict create]
set failedRuns [dict create]
set fh [open [file join $outDir fragility.csv] w]
puts $fh "case,damage_state,im,status,theta,beta,runs,exceeding,failed_runs"
foreach c $cases {
  set mine {}
  set nFailed 0
  foreach row $rows {
    if {[dict get $row case] ne $c} { continue }
    if {[dict get $row status] ne "ok"} { incr nFailed; continue }
    lappend mine $row
  }
  dict set failedRuns $c $nFailed
  foreach ds $damageStates {
    foreach im {pgv sa} {
      set pairs {}
      foreach row $mine { lappend pairs [dict get $row $im] [exceeds $row $ds] }
      set f [expr {[llength $pairs] ? [fragility::fit $pairs] : [dict create status none theta Inf beta NaN n 0 exceed 0]}]
      dict set fits $c $ds $im $f
      puts $fh [join [list $c $ds $im [dict get $f status] [dict get $f theta] [dict get $f beta] \
          [expr {int([dict get $f n])}] [expr {int([dict get $f exceed])}] $nFailed] ,]
    }
  }
}
close $fh

# The IDA fits: per case and damage state, the intensity at which each motion first exceeds it
# (its ladder in ascending order), fitted over the motions that reach it, with bootstrap bands.
set idaFits [dict create]
foreach c $cases {
  foreach ds $damageStates {
    foreach im {pgv sa} {
      # a motion's ladder ends at its first failed run: whether it would have exceeded there is
      # not known, so such a motion is counted apart, not as one that never exceeds
      set firsts {}; set never 0; set cut 0
      dict for {name m} $motions {
        set first ""; set stopped 0
        foreach level [lsort -real $pgvLadder] {
          if {$first ne "" || $stopped} { break }
          foreach row $rows {
            if {[dict get $row case] ne $c || [dict get $row motion] ne $name || [dict get $row level] != $level} { continue }
            if {[dict get $row status] ne "ok"} { set stopped 1 } elseif {[exceeds $row $ds]} { set first [dict get $row $im] }
          }
        }
        if {$first ne ""} { lappend firsts $first } elseif {$stopped} { incr cut } else { incr never }
      }
      set f [fragility::idaFit $firsts]
      dict set f never $never
      dict set f cut $cut
      if {[llength $firsts] >= 2} { set f [dict merge $f [fragility::bootstrap $firsts 1000 [expr {1000 + [llength $firsts]}]]] }
      dict set idaFits $c $ds $im $f
    }
  }
}
proc idaText {f unit} {
  if {[dict get $f n] == 0} { return "not reached ([dict get $f never] motions)" }
  set text [format "%.3g %s" [dict get $f theta] $unit]
  if {[dict exists $f thetaLow]} {
    append text [format " (90 %% %.3g-%.3g; beta %.2f)" [dict get $f thetaLow] [dict get $f thetaHigh] [dict get $f beta]]
  }
  append text [format ", %d of %d motions" [dict get $f n] [expr {[dict get $f n] + [dict get $f never] + [dict get $f cut]}]]
  if {[dict get $f cut] > 0} { append text [format " (%d stopped by a failed run)" [dict get $f cut]] }
  return $text
}

proc median {f unit} {
  switch -- [dict get $f status] {
    fit { return [format "%.3g %s (beta %.2f)" [dict get $f theta] $unit [dict get $f beta]] }
    separated { return [format "%.3g %s (step)" [dict get $f theta] $unit] }
    none { return "not reached" }
    all { return "always" }
  }
}
proc prob {f x} {
  switch -- [dict get $f status] {
    none { return 0.0 }
    all { return 1.0 }
    default { return [fragility::probability [dict get $f theta] [dict get $f beta] $x] }
  }
}

set md [open [file join $outDir fragility.md] w]
puts $md "# Fragility of the three-span bridge ($study study)\n"
puts $md [format "%d runs; this call ran %d of them on %d process(es) in %.1f s (%s). Isolated period T_iso = %.2f s (deck on the bearings' Keq at 250 %% shear strain). Motions:" \
    [llength $jobs] [dict get $summary ran] [getNP] $wall $summary $Tiso]
dict for {name m} $motions {
  puts $md [format "- %s: PGV %.3f m/s, Sa(T_iso, 5 %%) %.3f g at scale 1" $name [dict get $m pgv] [dict get $m sa]]
}
puts $md "\nPGV ladder (m/s): $pgvLadder. Lognormal fits by maximum likelihood (Baker 2015, binomial likelihood per run; Fisher scoring). Median (dispersion beta) of each damage state:\n"
puts $md "| damage state (limit) | IM | [join $cases { | }] |"
puts $md "|---|---|[string repeat ---| [llength $cases]]"
foreach ds $damageStates {
  # (joint, unseating and residual follow each run's gap where the gap is sampled: the defaults here)
  set limit [expr {[dict exists $limits $ds] ? [format %.3g [dict get $limits $ds]] : ($ds eq "service-lost" ? "unseating, residual, step or drift" : "HAZUS, mapped")}]
  foreach im {pgv sa} unit {m/s g} {
    set cells {}
    foreach c $cases { lappend cells [median [dict get $fits $c $ds $im] $unit] }
    puts $md "| $ds ($limit) | [string toupper $im] | [join $cells { | }] |"
  }
}
puts $md "\nIncremental dynamic analysis (Baker 2015, eqs. 3 and 4): the PGV at which each motion first exceeds the state, lognormal over the motions that reach it (the others counted; the median is then biased low), with the 90 % bootstrap band of the median (1000 resamples of the motions). The first exceeding level of the ladder is an upper bound of the motion's capacity, by up to one ladder step; a motion's ladder ends at its first failed run:\n"
puts $md "| damage state | [join $cases { | }] |"
puts $md "|---|[string repeat ---| [llength $cases]]"
foreach ds $damageStates {
  puts $md "| $ds | [join [lmap c $cases {idaText [dict get $idaFits $c $ds pgv] m/s}] { | }] |"
}
puts $md [format "\nThese rest on %d motions (%d records, %d pulses): a median from so few is uncertain by the band above, and the dispersion more so; the records are those the project ships, not a selection for a site or a hazard level. %s" \
    [dict size $motions] [llength [lsearch -all -inline [lmap {k v} $motions {dict get $v kind}] record]] [llength $pulsePeriods] \
    [expr {$sampleModels ? "Each motion ran on its own realisation of the bridge (modelling uncertainty, see ensemble.tcl)." : "No modelling uncertainty (the smoke study)."}]]
set failedText {}
dict for {c n} $failedRuns { lappend failedText "$c $n" }
puts $md "\nRuns whose analysis failed (left out of the fits): [join $failedText {, }].\n"
if {"pound" in $cases && "countermeasure" in $cases} {
  puts $md "## Does the countermeasure lower the probability of losing serviceability?\n"
  puts $md "Service lost: a girder end off its seat, a residual offset or vertical step at a joint past its limit, or a pier past the JRA residual drift (the report's verdict; the peak opening is damage to the joint).\n"
  puts $md "| PGV (m/s) | P(service lost), pound | P(service lost), countermeasure | countermeasure - pound |"
  puts $md "|---|---|---|---|"
  foreach x {0.5 1.0 1.5 2.0} {
    set p1 [prob [dict get $fits pound service-lost pgv] $x]
    set p2 [prob [dict get $fits countermeasure service-lost pgv] $x]
    puts $md [format "| %.1f | %.2f | %.2f | %+.2f |" $x $p1 $p2 [expr {$p2 - $p1}]]
  }
  set largest {}
  foreach c $cases {
    set top 0.0
    foreach row $rows { if {[dict get $row case] eq $c && [dict get $row status] eq "ok"} { set top [expr {max($top, [dict get $row opening])}] } }
    lappend largest [format "%s %.3f m" $c $top]
  }
  puts $md "\nLargest peak opening of a joint over all runs: [join $largest {, }]."
  puts $md "\nWhat the countermeasure changes, median PGV of pounding -> countermeasure (maximum likelihood): [join [lmap ds {residual step unseating service-lost hazus-extensive} {format "%s %s -> %s" $ds [median [dict get $fits pound $ds pgv] m/s] [median [dict get $fits countermeasure $ds pgv] m/s]}] {; }]."
}
close $md

# Plots: one panel per damage state, the fitted curves of the cases and, for PGV, the fraction of
# runs exceeding at each level of the ladder.
set pointsFile [file join $outDir fragility-points.dat]
set fh [open $pointsFile w]
foreach ds $damageStates {
  foreach c $cases {
    puts $fh "# $ds $c"
    foreach level $pgvLadder {
      set n 0; set k 0
      foreach row $rows {
        if {[dict get $row case] ne $c || [dict get $row status] ne "ok" || [dict get $row level] != $level} { continue }
        incr n; incr k [exceeds $row $ds]
      }
      if {$n > 0} { puts $fh "$level [expr {double($k) / $n}]" }
    }
    puts $fh "\n"
  }
}
close $fh
set colors {nopound #1f77b4 pound #d62728 countermeasure #2ca02c}
set labels [list "PGV (m/s)" [format "Sa(T_{iso} = %.2f s, 5 %%) (g)" $Tiso]]
foreach im {pgv sa} label $labels xmax {2.2 3.0} {
  set gp "set terminal pngcairo size 1800,1100 font ',10'\nset output '[file join $outDir fragility-$im.png]'\n"
  append gp "set multiplot layout 3,4 title 'Fragility of the bridge ($study study, lognormal maximum-likelihood fits)'\n"
  append gp "set yrange \[0:1\]\nset xrange \[0.01:$xmax\]\nset xlabel '$label'\nset ylabel 'P(exceed)'\nset key bottom right\nset samples 400\n"
  set block 0
  foreach ds $damageStates {
    set plots {}
    foreach c $cases {
      set f [dict get $fits $c $ds $im]
      set color [dict get $colors $c]
      switch -- [dict get $f status] {
        fit { lappend plots [format "norm(log(x/%.6g)/%.6g) lw 2 lc rgb '%s' title '%s'" [dict get $f theta] [dict get $f beta] $color $c] }
        separated { lappend plots [format "(x >= %.6g ? 1 : 0) lw 2 lc rgb '%s' title '%s (step)'" [dict get $f theta] $color $c] }
        none { lappend plots "0 lw 2 dt 2 lc rgb '$color' title '$c (not reached)'" }
        all { lappend plots "1 lw 2 dt 2 lc rgb '$color' title '$c (always)'" }
      }
      if {$im eq "pgv"} { lappend plots "'$pointsFile' index [expr {$block}] with points pt 7 lc rgb '$color' notitle" }
      incr block
    }
    append gp "set title '$ds'\nplot [join $plots {, }]\n"
  }
  append gp "unset multiplot\n"
  if {[auto_execok gnuplot] ne ""} {
    if {[catch {exec gnuplot << $gp} err]} { puts "gnuplot: $err" }
  }
}
puts "fragility: [file join $outDir fragility.md]"

# The smoke study checks itself (the test suite runs it): every run completed, every fit written,
# and a rerun runs nothing.
if {$study eq "smoke"} {
  source [file join $here .. lib check.tcl]
  checkTrue "every run of the smoke study completed ($summary)" \
      [expr {[dict get $summary ok] == [llength $jobs] && [llength $jobs] == 8}]
  set fh [open [file join $outDir fragility.csv]]; set n [llength [split [string trim [read $fh]] \n]]; close $fh
  checkTrue "a fit per case, damage state and intensity measure ($n lines)" \
      [expr {$n == 1 + [llength $cases] * [llength $damageStates] * 2}]
  set again [ensemble run $jobs bridgeRun -out [file join $outDir runs]]
  checkTrue "a rerun skips every run ($again)" [expr {[dict get $again ran] == 0 && [dict get $again skipped] == [llength $jobs]}]
  finish
}
