# SPDX-License-Identifier: MIT
# A recorder that cannot write (a full disk, here Linux's /dev/full, whose every write fails with
# ENOSPC) makes `analyze` and `record` raise a Tcl error naming the file; the analysis stops at the
# step whose rows could not be written, and the other recorders keep every step up to it.
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] .. lib expect-error.tcl]

if {![file writable /dev/full]} {
  puts "SKIPPED: /dev/full is not available"
  finish
  return
}

# An SDOF oscillator: k = 4 pi^2 m, period 1 s, under a constant unit force.
model basic -ndm 1 -ndf 1
node 1 0.0
node 2 0.0 -mass 1.0
fix 1 1
uniaxialMaterial Elastic 1 [expr {4.0 * acos(-1) ** 2}]
element zeroLength 1 1 2 -mat 1 -dir 1
timeSeries Constant 1
pattern Plain 1 1 { load 2 1.0 }
recorder Node -file good.out -time -node 2 -dof 1 disp
recorder Node -file /dev/full -time -node 2 -dof 1 disp
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1e-12 10
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient

expectError "analyze with a recorder on a full disk" { analyze 10 0.01 } {recorder 1 /dev/full "No space left on device" stopped}
check "the analysis stopped after its first step" [getTime %.17g] 0.01 1e-12
set f [open good.out]; set lines [split [string trim [read $f]] "\n"]; close $f
checkTrue "the other recorder keeps the step (rows: [llength $lines])" [expr {[llength $lines] == 1}]
expectError "record with a recorder on a full disk" { record } {/dev/full "No space left on device"}
remove recorder 1
checkTrue "without the failing recorder analyze runs on (code 0)" [expr {[analyze 4 0.01] == 0}]
set f [open good.out]; set lines [split [string trim [read $f]] "\n"]; close $f
checkTrue "the good recorder has every committed step (rows: [llength $lines], expected 6)" [expr {[llength $lines] == 6}]
expectError "an envelope recorder on a full disk" {
  recorder EnvelopeNode -file /dev/full -node 2 -dof 1 disp
  analyze 1 0.01
} {/dev/full "No space left on device"}
finish
