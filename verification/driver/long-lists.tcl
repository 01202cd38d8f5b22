# SPDX-License-Identifier: MIT
# Commands given very long lists answer at once (the argument reader, equalDOF's dof checks and
# the domain's constraint checks are linear or n log n in the list's length; before, a list of
# 100000 dofs took minutes): each command below either completes or fails with the error of its
# first bad argument. A hang here shows as the test's time-out, not as a time measured here.
source [file join [file dirname [info script]] .. lib check.tcl]

model basic -ndm 2 -ndf 3
set n 50000
for {set i 1} {$i <= $n} {incr i} { node $i [expr {double($i)}] 0.0 }

catch {equalDOF 1 2 {*}[lrepeat 100000 1]} msg
checkTrue "equalDOF with 100000 repeated dofs: the second is refused ($msg)" \
    [string match "*argument 4 (dof) is given twice*" $msg]
set many {}
for {set i 1} {$i <= 100000} {incr i} { lappend many $i }
catch {equalDOF 1 2 {*}$many} msg
checkTrue "equalDOF with dofs 1..100000: dof 4 is refused before anything is formed ($msg)" \
    [string match "*argument 6 (dof) must be a dof of both nodes, 1 to 3*" $msg]

set nodes {}
for {set i 2} {$i <= $n} {incr i} { lappend nodes $i }
checkTrue "rigidDiaphragm of [llength $nodes] nodes completes" \
    [expr {[catch {rigidDiaphragm 3 1 {*}$nodes}] == 0}]
catch {rigidDiaphragm 3 1 2} msg
checkTrue "a second diaphragm on the same nodes is refused ($msg)" \
    [string match "*already constrained*" $msg]
checkTrue "getNodeTags lists the $n nodes" [expr {[llength [getNodeTags]] == $n}]
finish
