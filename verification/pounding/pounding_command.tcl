# SPDX-License-Identifier: MIT
# The `pounding` command between two girder ends: pairs both ways, numbering tag,
# tag+1, ..., all-or-nothing on errors, and a head-on impact of two girder ends of mass m each in
# -ndf 3 and -ndf 6 models. Every contactor sits on a corner of the opposite face (corner contact;
# each node is in two pairs: as contactor and as face node). Closed forms (e = 1): momentum
# m v1 + m v2 conserved and the velocities exchanged (equal masses, elastic impact); the force
# of a corner contact goes to that corner node only.
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] lib contact.tcl]

set K 1.0e6
set m 4.0
set v0 1.0
set gap 0.01

proc girders {ndf} {
  global m gap
  wipe
  model basic -ndm 3 -ndf $ndf
  set i 0
  foreach {y z} {-1 -0.5  1 -0.5  1 0.5  -1 0.5} {
    incr i
    node [expr {10 + $i}] 0.0 $y $z
    node [expr {20 + $i}] $gap $y $z
    foreach n [list [expr {10 + $i}] [expr {20 + $i}]] {
      if {$ndf == 3} { fix $n 0 1 1; mass $n [expr {$m/4}] 0 0 } else {
        fix $n 0 1 1 1 1 1; mass $n [expr {$m/4}] 0 0 0 0 0 }
    }
  }
}

# --- command behaviour ---------------------------------------------------------------------
girders 3
set made [pounding 100 -side1 {11 12 13 14} {11 12 13 14} -side2 {21 22 23 24} {21 24 23 22} -K $K]
checkTrue "pounding returns tags 100..107 ($made)" [expr {$made eq {100 101 102 103 104 105 106 107}}]
checkTrue "elements exist" [expr {[getEleTags] eq $made}]
set before [getEleTags]
checkTrue "taken tag is an error" [catch {pounding 105 -side1 {11} {11 12 13 14} -side2 {21} {21 24 23 22} -K $K}]
checkTrue "nothing created after a tag error" [expr {[getEleTags] eq $before}]
# Side-1 face listed with its normal pointing away from girder 2: elements 200 and 201 (side-1
# contactors against face 2) are added, 202 (node 21 against face 1) fails; 200 and 201 must be
# removed again.
checkTrue "wrong-side face is an error" [catch {pounding 200 -side1 {11 12} {14 13 12 11} -side2 {21} {21 24 23 22} -K $K} msg]
checkTrue "all-or-nothing: nothing left from the failed command" [expr {[getEleTags] eq $before}]
checkTrue "error names the failing element 202 ($msg)" [string match "*element 202,*" $msg]
checkTrue "missing -K is an error" [catch {pounding 300 -side1 {11} {11 12 13 14} -side2 {21} {21 24 23 22}}]

# --- head-on impact of the two girder ends ---------------------------------------------------
foreach ndf {3 6} {
  girders $ndf
  pounding 1 -side1 {11 12 13 14} {11 12 13 14} -side2 {21 22 23 24} {21 24 23 22} -K $K -search 0.5
  set Tc [expr {$::pi*sqrt(($m/8)/(2*$K))}]  ;# corner pair: two pairs in parallel, masses m/4
  set dt [expr {$Tc/40}]
  set tp [expr {ceil(0.002/$dt)*$dt}]
  timeSeries Constant 1
  if {$ndf == 3} {
    pattern Plain 1 1 { foreach n {11 12 13 14} { load $n [expr {$m/4*$v0/$tp}] 0 0 } }
  } else {
    pattern Plain 1 1 { foreach n {11 12 13 14} { load $n [expr {$m/4*$v0/$tp}] 0 0 0 0 0 } }
  }
  constraints Plain; numberer Plain; system FullGeneral
  test NormDispIncr 1e-12 50; algorithm Newton
  integrator Newmark 0.5 0.25; analysis Transient
  set failed [runUntil $dt $tp]
  remove loadPattern 1
  incr failed [runUntil $dt [expr {$tp + $dt}]]
  set v1 [nodeVel 11 1]; set v2 [nodeVel 21 1]
  set peak 0.0
  set others 0.0
  incr failed [runUntil $dt [expr {$tp + 0.05}] {
    set f [eleResponse 5 force]
    set ndf_ [expr {[llength $f]/5}]
    # element 5: contactor 21 against face {11 12 13 14}; 21 faces corner a = 11
    set ::peak [expr {max($::peak, abs([lindex $f $ndf_]))}]
    foreach j {2 3 4} { set ::others [expr {max($::others, abs([lindex $f [expr {$j*$ndf_}]]))}] }
    expr {[lindex [eleResponse 1 impulse] 0] > 0 && [lindex [eleResponse 1 gap] 0] > 0}
  }]
  checkTrue "ndf $ndf: every step converged" [expr {$failed == 0}]
  set u1 [nodeVel 11 1]; set u2 [nodeVel 21 1]
  checkAbs "ndf $ndf: momentum conserved" [expr {$m*($u1 + $u2)}] [expr {$m*($v1 + $v2)}] 1e-9
  # Newmark (second order) with 40 steps per contact: error O((pi/40)^2)/2.
  set tol [expr {0.5*pow($::pi/40, 2)}]
  checkAbs "ndf $ndf: velocities exchanged, girder 1 stops" $u1 $v2 $tol
  checkAbs "ndf $ndf: velocities exchanged, girder 2 takes v1" $u2 $v1 $tol
  checkTrue "ndf $ndf: corner contact loads only the facing corner (peak [format %.3g $peak], others $others)" \
      [expr {$peak > 0 && $others < 1e-9*$peak}]
}
finish
