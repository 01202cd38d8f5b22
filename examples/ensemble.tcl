# SPDX-License-Identifier: MIT
# A record ensemble: an isolated deck (one span, 600 t, on high-damping rubber bearings) under the
# three records in verification/data at three scales, 9 runs (units kN, m, s, t). Prints one line
# per run: peak deck displacement, bearing shear strain, base shear, residual displacement.
#   dabs examples/ensemble.tcl ?outDir?                 (one process)
#   mpirun -n 2 dabs-mp examples/ensemble.tcl ?outDir?  (two processes share the runs)
set outDir [expr {$argc > 0 ? [lindex $argv 0] : "ensemble-out"}]   ;# results go here
set data [file normalize [file join [file dirname [info script]] .. verification data]]
set M 600.0; set A 3.2; set Tr 0.2; set tEnd 20.0                    ;# t, m^2, m, s
# One run: builds the model, runs the record, returns a dict of results (code 0 = completed)
proc deck {job} {
  global data M A Tr tEnd
  dict with job {}                                    ;# sets record and scale from the job
  model basic -ndm 3 -ndf 6
  node 1 0 0 0; node 2 0 0 0 -mass $M $M $M 0 0 0     ;# ground, deck
  fix 1 1 1 1 1 1 1; fix 2 0 0 1 1 1 1                ;# the deck moves in X and Y only
  # HDR set (a) of verification/bearing/fitted-parameters.md for A m^2 of rubber, Tr m thick
  biaxialMaterial Yoshida 1 [expr {0.435794*1000*$A}] [expr {0.0683367*$Tr}] 0.115167 0.831926 0.698464 0.0393774 0.000947439
  element yoshidaBearing 1 1 2 1 -Tr $Tr -Kv 1.0e7
  # The record (in g; PEER header gives its time step) along X, scaled
  timeSeries Path 1 -filePath [file join $data $record] -factor [expr {9.81*$scale}]
  pattern UniformExcitation 1 1 -accel 1
  constraints Plain; numberer Plain; system BandGeneral
  test NormDispIncr 1e-8 30; algorithm Newton; integrator Newmark 0.5 0.25; analysis Transient
  set peak 0.0; set shear 0.0; set code 0
  for {set i 0} {$i < int($tEnd/0.01) && $code == 0} {incr i} {
    set code [analyze 1 0.01]
    set peak [expr {max($peak, abs([nodeDisp 2 1]))}]
    set shear [expr {max($shear, abs([lindex [eleResponse 1 basicForce] 1]))}]
  }
  # damage: 0 intact, 1 past the 250 % design strain, 2 past the 300 % failure strain
  return [list code $code peak $peak strain [expr {$peak/$Tr}] shear $shear residual [nodeDisp 2 1] \
      damage [eleResponse 1 damage]]
}
# The jobs: every record at every scale; `id` names each run's result file
set jobs {}
foreach record {RSN1120_KOBE_TAK090.AT2 elCentro.at2 ARL360.at2} {
  foreach scale {0.5 1.0 1.5} {
    lappend jobs [list id [file rootname $record]-x$scale record $record scale $scale]
  }
}
# Run them: on one process, or shared among the MPI processes; a rerun skips finished runs
set summary [ensemble run $jobs deck -out $outDir]
if {[dict get $summary failed] + [dict get $summary error] > 0} { puts "FAILED: $summary"; exit 1 }
if {[getPID] != 0} { return }                         ;# only process 0 reports
# The table: one line per run from results.csv (one row per job, columns named in its header)
set fh [open [dict get $summary file]]; set lines [split [string trim [read $fh]] \n]; close $fh
set header [split [lindex $lines 0] ,]
puts [format "%-26s %6s %9s %9s %10s %9s %-9s %s" run scale "peak (m)" strain "shear (kN)" "resid (m)" bearing process]
foreach line [lrange $lines 1 end] {
  set row {}; foreach k $header v [split $line ,] { dict set row $k $v }
  dict with row {
    puts [format "%-26s %6s %9.3f %8.0f%% %10.0f %9.3f %-9s %s" $job $scale $peak [expr {100*$strain}] \
        $shear $residual [lindex {ok >250% failed} [expr {int($damage)}]] $rank]
    if {!($peak > 0 && $peak < 10)} { puts "FAILED: run $job"; exit 1 }   ;# a run that went astray
  }
}
puts "on [getNP] process(es): $summary"
