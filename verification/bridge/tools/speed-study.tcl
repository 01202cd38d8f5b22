# SPDX-License-Identifier: MIT
# Speed against error of the bridge case study and its stability runs.
#
#   dabs verification/bridge/tools/speed-study.tcl ?case? ?motion? ?outDir? ?speed|stability|both?
#
# Speed: the case (default pound) is run at dt = 0.01 ... 0.0005 s with Newmark (average
# acceleration) and HHT (alpha = 0.95, OpenSees convention), each at NormDispIncr tolerances
# 1e-4 and 1e-6 m. The finest run (dt 0.0005, Newmark, 1e-6) is the reference; each run's error
# is the largest relative difference from it over the reported quantities: peak gaps (by
# magnitude) and residual gaps (both joints, both directions; residuals relative to the peak of
# the same gap, since they are near zero) and peak bearing shear strains. A run at half the
# reference step estimates the reference's own error. Writes speed.csv, speed.md and speed.png in outDir (default
# ./bridge-speed) and names the fastest run within 1 % on every quantity.
#
# Stability: the three cases at scales 0.5, 1.0 and 1.5 at the default settings; reports
# completion, failed (then sub-stepped) steps and the peak bearing strain (stability.md).
set ::bridgeLibraryOnly 1
source [file join [file dirname [info script]] .. bridge.tcl]
set case   [expr {$argc > 0 ? [lindex $argv 0] : "pound"}]
set motion [expr {$argc > 1 ? [lindex $argv 1] : "auto"}]
set outDir [expr {$argc > 2 ? [lindex $argv 2] : "bridge-speed"}]
set parts  [expr {$argc > 3 ? [lindex $argv 3] : "both"}]
file mkdir $outDir

source [file join [file dirname [info script]] speed-error.tcl]

if {$parts ne "stability"} {
set runs {}
set dts {0.01 0.005 0.0025 0.001 0.0005}
set ref [runCase $case 1.0 0.0005 Newmark 1e-6 $motion]
set refQ [quantities $ref]
# The reference's own error: a run at half its step, both with contact steps of half the
# reference step, compared with it on the same quantities.
set saved $::contactDt
set ::contactDt 0.00025
set half [runCase $case 1.0 0.00025 Newmark 1e-6 $motion]
set ::contactDt $saved
lassign [errorOf [quantities $half] $refQ] refErr refWhich
puts "reference check (dt 0.00025, contact steps 0.00025): [format %.3g $refErr] on $refWhich"
set csv [open [file join $outDir speed.csv] w]
puts $csv "integrator,tol,dt,wall_s,steps,contact_steps,iterations,factorizations,failed,max_rel_error,worst_quantity"
set best ""
foreach integrator {Newmark HHT} {
  foreach tol {1e-4 1e-6} {
    foreach dt $dts {
      if {$integrator eq "Newmark" && $tol == 1e-6 && $dt == 0.0005} { set r $ref } else {
        set r [runCase $case 1.0 $dt $integrator $tol $motion]
      }
      lassign [errorOf [quantities $r] $refQ] err which
      set st [dict get $r stats]
      set line [format "%s,%g,%g,%.2f,%d,%d,%d,%d,%d,%.4g,%s" $integrator $tol $dt [dict get $r wall] \
          [dict get $st steps] [dict get $r contactSubsteps] [dict get $st iterations] [dict get $st factorizations] \
          [dict get $st failedSteps] $err $which]
      puts $csv $line; flush $csv
      puts $line
      lappend runs [list $integrator $tol $dt [dict get $r wall] $err $which [dict get $r completed] \
          [dict get $st steps] [dict get $r contactSubsteps] [dict get $st failedSteps]]
      if {$err <= 0.01 && [dict get $r completed] && !($integrator eq "Newmark" && $tol == 1e-6 && $dt == 0.0005)} {
        if {$best eq "" || [dict get $r wall] < [lindex $best 3]} { set best [lindex $runs end] }
      }
    }
  }
}
close $csv
set md [open [file join $outDir speed.md] w]
puts $md "# Speed against error ($case case, reference: Newmark, dt 0.0005 s, tol 1e-6)\n"
puts $md "Every run steps at most $::contactDt s while a joint is closed or closing, with the step cut at"
puts $md "each predicted first contact (the driver's contactStepping, see the README). Wall times of one run, one after"
puts $md "another on the same machine; errors are the largest relative difference from the reference over"
puts $md "the peak and residual gaps (both joints, both directions; residuals relative to the peak) and"
puts $md "the peak bearing strains. The reference's own error, from a run at half its step (and contact"
puts $md "steps of 0.00025 s): [format %.2f%% [expr {100 * $refErr}]] on $refWhich.\n"
puts $md "| integrator | tol (m) | dt (s) | wall (s) | steps | of them contact steps | failed steps | largest relative error | on |"
puts $md "|---|---:|---:|---:|---:|---:|---:|---:|---|"
foreach r $runs {
  lassign $r i t d w e q c n nc nf
  puts $md [format "| %s | %g | %g | %.2f | %d | %d | %d | %.2f%% | %s |" $i $t $d $w $n $nc $nf [expr {100 * $e}] $q]
}
if {$best ne ""} {
  puts $md "\nFastest within 1 % on every quantity: [lindex $best 0], tol [lindex $best 1], dt [lindex $best 2] s ([format %.2f [lindex $best 3]] s)."
} else { puts $md "\nNo run other than the reference is within 1 % on every quantity." }
puts $md "\n!\[wall time against error\](speed.png)"
close $md
if {[auto_execok gnuplot] ne ""} {
  set gp [open [file join $outDir speed.gp] w]
  puts $gp "set terminal pngcairo size 900,600 font ',10'; set output '[file join $outDir speed.png]'"
  puts $gp "set datafile separator ','; set logscale xy; set grid; set key bottom left"
  puts $gp "set xlabel 'wall time (s)'; set ylabel 'largest relative error vs reference'"
  puts $gp "set title 'Bridge case study: speed against error'"
  set plotParts {}
  set pt 5
  foreach integrator {Newmark HHT} {
    foreach tol {1e-4 1e-6} {
      incr pt 2
      lappend plotParts "'[file join $outDir speed.csv]' using ((strcol(1) eq '$integrator' && \$2 == $tol && \$10 > 0) ? \$4 : 1/0):10 with linespoints pt $pt title '$integrator tol $tol'"
    }
  }
  lappend plotParts "0.01 with lines dt 2 lc rgb 'black' title '1 %'"
  puts $gp "plot [join $plotParts {, }]"
  close $gp
  catch {exec gnuplot [file join $outDir speed.gp] 2>@1} err
}
if {$best ne ""} { puts "fastest within 1 %: $best" }

}

# Stability runs at the default settings.
if {$parts eq "speed"} { return }
set md [open [file join $outDir stability.md] w]
puts $md "# Stability: three cases, motion scaled by 0.5, 1.0, 1.5 (defaults: $defaultIntegrator, dt $defaultDt, tol $defaultTol)\n"
puts $md "| case | scale | completed | steps | of them contact steps | failed steps | sub-stepped steps | loosened steps | iterations | impacts PC2 / PC3 | peak bearing strain | failed bearings | wall (s) |"
puts $md "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
foreach c {nopound pound countermeasure} {
  foreach sc {0.5 1.0 1.5} {
    set r [runCase $c $sc $defaultDt $defaultIntegrator $defaultTol $motion]
    set st [dict get $r stats]
    set peakStrain 0.0; set nFailed 0
    foreach bt {2011 2012 3011 3012} {
      set peakStrain [expr {max($peakStrain, [dict get $r peak strain$bt])}]
      if {[dict get $r peak damage$bt] >= 2} { incr nFailed }
    }
    set line [format "| %s | %.1f | %s | %d | %d | %d | %d | %d | %d | %s | %.0f%% | %d | %.1f |" $c $sc \
        [expr {[dict get $r completed] ? "yes" : "NO"}] [dict get $st steps] [dict get $r contactSubsteps] \
        [dict get $st failedSteps] [dict get $st subSteppedSteps] [dict get $r loosened] [dict get $st iterations] \
        [join [dict get $r impacts] " / "] [expr {100 * $peakStrain}] $nFailed [dict get $r wall]]
    puts $md $line; flush $md
    puts $line
  }
}
close $md
