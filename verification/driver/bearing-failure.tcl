# SPDX-License-Identifier: MIT
# A yoshidaBearing pushed past its failure shear strain (3.0 = 300 %, the default limit) under
# -afterFailure keep, release and stop: analysisStatistics counts the failed bearing, the console
# says so once, and `stop` ends the analysis with code -5 at the step in which the limit was
# reached. The shear strain is the imposed displacement over Tr, so the step of failure follows
# from the input: u = 0.01 m per step, Tr = 0.2 m, strain 3.0 at step 60.
source [file join [file dirname [info script]] .. lib check.tcl]

set model {
  model basic -ndm 3 -ndf 6
  node 1 0.0 0.0 0.0
  node 2 0.0 0.0 0.0
  fix 1 1 1 1 1 1 1
  fix 2 0 1 0 1 1 1
  biaxialMaterial Yoshida 1 150.0 0.012 2.0 0.0 0.0 1.0 0.0
  element yoshidaBearing 1 1 2 1 -Tr 0.2 -Kv 1.0e6 -afterFailure $after
  timeSeries Linear 1
  pattern Plain 1 1 { sp 2 1 0.01 }
  constraints Transformation
  numberer Plain
  system BandGeneral
  test NormDispIncr 1e-10 20
  algorithm Newton
  integrator LoadControl 1.0
  analysis Static
}

# Runs the model in a separate dabs so that its console (stderr) can be read.
proc runSeparately {after steps} {
  global model
  set f [open failure-$after.tcl w]
  puts $f [string map [list {$after} $after] $model]
  puts $f "set code \[analyze $steps\]"
  puts $f {puts "RESULT $code [getTime %.17g] [eleResponse 1 maxShearStrain] [dict get [analysisStatistics] failedBearings]"}
  close $f
  set out [exec [info nameofexecutable] failure-$after.tcl 2>@1]
  set result [lrange [lindex [regexp -all -inline {RESULT [^\n]*} $out] 0] 1 end]
  set notices [regexp -all {yoshidaBearing 1 reached its failure shear strain 3} $out]
  return [list $result $notices]
}

lassign [runSeparately keep 100] r notices
lassign $r code time maxStrain failed
checkTrue "keep: analyze returns 0 (got $code) and runs to the end (time $time)" [expr {$code == 0 && abs($time - 100.0) < 1e-9}]
check "keep: the bearing went on to 500 % shear strain" $maxStrain 5.0 1e-9
checkTrue "keep: analysisStatistics says failedBearings 1 (got $failed)" [expr {$failed == 1}]
checkTrue "keep: the console says so once (got $notices)" [expr {$notices == 1}]

lassign [runSeparately release 100] r notices
lassign $r code time maxStrain failed
checkTrue "release: analyze returns 0 (got $code), failedBearings 1 (got $failed), said once (got $notices)" \
  [expr {$code == 0 && $failed == 1 && $notices == 1}]

lassign [runSeparately stop 100] r notices
lassign $r code time maxStrain failed
checkTrue "stop: analyze returns -5 (got $code)" [expr {$code == -5}]
check "stop: the analysis ends at the step that reached 300 % (time 60)" $time 60.0 1e-9
check "stop: the shear strain there is the limit 3.0" $maxStrain 3.0 1e-9
checkTrue "stop: failedBearings 1 (got $failed), said once (got $notices)" [expr {$failed == 1 && $notices == 1}]

# Below the limit nothing is said.
lassign [runSeparately stop 50] r notices
lassign $r code time maxStrain failed
checkTrue "below the limit: code 0, failedBearings 0, nothing said" [expr {$code == 0 && $failed == 0 && $notices == 0}]
finish
