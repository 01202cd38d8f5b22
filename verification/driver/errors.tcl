# SPDX-License-Identifier: MIT
# Bad input gives Tcl errors that `catch` sees, whose messages name the command and the argument,
# and leaves the model as it was; a singular system is a failed step (negative return code), not
# an error; recorders keep what was written before a failed step.
#
# Source: the required behaviour ("Behaviour on bad input", "Recorders"); the
# expected values (tags, displacements, recorded lines) follow from the script's own input.
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] .. lib expect-error.tcl]

# --- analysis before a model ---
wipe
expectError "analyze before any model" { analyze 1 } {analyze}
expectError "eigen before any model" { eigen 1 } {eigen}

# --- a small 2D model ---
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 100.0 0.0
fix 1 1 1 1
geomTransf Linear 1
uniaxialMaterial Elastic 1 1000.0
element elasticBeamColumn 1 1 2 10.0 1000.0 100.0 1
set state [modelState]
checkTrue "model built: nodes {1 2}, elements {1}" [expr {$state eq {{1 2} 1}}]

expectError "node: wrong coordinate count (ndm 2 given 1)" { node 3 5.0 } {node 3}
expectUnchanged "after node with wrong coordinate count" $state
expectError "node: wrong coordinate count (ndm 2 given 3)" { node 3 5.0 1.0 2.0 } {node}
expectUnchanged "after node with 3 coordinates" $state
expectError "node: missing arguments" { node } {node}
expectError "node: non-number coordinate" { node 3 abc 0.0 } {node abc}
expectUnchanged "after node with a non-number" $state
expectError "node: duplicate tag" { node 2 0.0 50.0 } {node 2}
checkTrue "duplicate node: node 2 keeps its coordinates" [expr {[nodeCoord 2 1] == 100.0}]
expectUnchanged "after duplicate node" $state
expectError "element: duplicate tag" { element elasticBeamColumn 1 1 2 10.0 1000.0 100.0 1 } {element 1}
expectError "element: unknown node" { element elasticBeamColumn 2 1 99 10.0 1000.0 100.0 1 } {element 99}
expectUnchanged "after element to an unknown node" $state
expectError "element: unknown transformation" { element elasticBeamColumn 2 1 2 10.0 1000.0 100.0 7 } {element 7}
expectUnchanged "after element with unknown geomTransf" $state
expectError "element: non-number area" { element elasticBeamColumn 2 1 2 big 1000.0 100.0 1 } {element big}
expectError "element: wrong count" { element elasticBeamColumn 2 1 2 10.0 } {element}
expectError "element truss: unknown material" { element truss 2 1 2 1.0 42 } {truss 42}
expectUnchanged "after element errors" $state
expectError "fix: unknown node" { fix 99 1 1 1 } {fix 99}
expectError "fix: wrong number of dofs" { fix 2 1 1 } {fix}
expectError "uniaxialMaterial: duplicate tag" { uniaxialMaterial Elastic 1 5.0 } {uniaxialMaterial 1}
expectError "uniaxialMaterial: unknown type" { uniaxialMaterial NoSuchMaterial 9 1.0 } {NoSuchMaterial}
expectError "nodeDisp: unknown node" { nodeDisp 99 1 } {nodeDisp 99}
expectError "eleResponse: unknown element" { eleResponse 99 force } {99}
expectError "timeSeries: unknown type" { timeSeries Bogus 3 } {Bogus}
expectError "pattern: unknown time series" { pattern Plain 5 77 { } } {77}
expectError "load: unknown node" { pattern Plain 6 {Linear} { load 99 1.0 0.0 0.0 } } {99}
expectError "integrator: unknown type" { integrator NoSuchIntegrator } {NoSuchIntegrator}
expectError "test: non-number tolerance" { test NormDispIncr tiny 10 } {test tiny}
expectUnchanged "after load/analysis errors" $state

# --- element between nodes of the wrong dof count ---
model basic -ndm 2 -ndf 2
node 10 0.0 100.0
set state2 [modelState]
expectError "truss between a 3-dof node and a 2-dof node" { element truss 5 2 10 1.0 1 } {truss dof}
expectUnchanged "after element between nodes of different dof counts" $state2
# a truss between two 2-dof nodes is fine in ndf 2
node 11 50.0 100.0
fix 10 1 1
element truss 6 10 11 1.0 1
set state3 [modelState]
checkTrue "truss between 2-dof nodes accepted" [expr {[lsearch [lindex $state3 1] 6] >= 0}]

# --- singular system: node 11 has no vertical stiffness ---
timeSeries Linear 1
pattern Plain 1 1 { load 11 1.0 1.0 }
constraints Plain; numberer Plain; system BandGeneral
test NormDispIncr 1e-10 10
algorithm Newton
integrator LoadControl 1.0
analysis Static
set rc [catch {analyze 1} result]
checkTrue "singular system: analyze is not a Tcl error" [expr {$rc == 0}]
checkTrue "singular system: analyze returns a negative code (got $result)" [expr {$rc == 0 && $result < 0}]
checkAbs "singular system: time stays at the last converged step (0)" [getTime %.17g] 0.0 0.0
checkAbs "singular system: node 11 displacement stays 0" [nodeDisp 11 1] 0.0 0.0
expectUnchanged "after the failed analysis" $state3
wipe

# --- recorders keep what was written before a failed step ---
set file [file join [pwd] errors-recorder.out]
file delete -force $file
model basic -ndm 1 -ndf 1
node 1 0.0
node 2 0.0
fix 1 1
uniaxialMaterial ElasticPP 1 100.0 0.05   ;# fy = 5
element zeroLength 1 1 2 -mat 1 -dir 1
timeSeries Linear 1
pattern Plain 1 1 { load 2 1.0 }
recorder Node -file $file -time -node 2 -dof 1 disp
constraints Plain; numberer Plain; system BandGeneral
test NormDispIncr 1e-12 20
algorithm Newton
integrator LoadControl 2.0
analysis Static
set codes {}
for {set i 1} {$i <= 3} {incr i} { lappend codes [analyze 1] }
checkTrue "EPP spring: two steps converge, the third (load 6 > fy 5) fails (codes $codes)" \
  [expr {[lindex $codes 0] == 0 && [lindex $codes 1] == 0 && [lindex $codes 2] < 0}]
# read the file while the recorder is still open: it was flushed at the end of each analyze
set f [open $file]; set lines [split [string trim [read $f]] "\n"]; close $f
checkTrue "recorder: the two converged steps are in the file (got [llength $lines] lines)" [expr {[llength $lines] == 2}]
set last [lindex $lines end]
check "recorder: last line time = 4" [lindex $last 0] 4.0 1e-12
check "recorder: last line disp = 4/k = 0.04" [lindex $last 1] 0.04 1e-10
# an error in the script after this point must not lose the file either
catch { node 2 0.0 }
wipe
set f [open $file]; set lines2 [split [string trim [read $f]] "\n"]; close $f
checkTrue "recorder: the file is intact after an error and wipe" [expr {$lines2 eq $lines}]
finish
