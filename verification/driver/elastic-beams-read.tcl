# SPDX-License-Identifier: MIT
# What is read of elastic beams whose force the analysis forms as one product with their
# assembled stiffness (their states formed only when read): eleForce, eleResponse, an element
# recorder at every step, reactions, the state after a failed step, and the same beams once a
# member load makes the analysis update them again.
#
# Source: elementary beam theory for a cantilever of length L (e.g. Gere & Timoshenko, Mechanics
# of Materials, Appendix G, cases 1 and 4): tip load P: tip deflection P L^3 / (3 E I), moment
# P x' at a distance x' from the tip; uniform load w: tip deflection w L^4 / (8 E I), moment
# w x'^2 / 2. Cubic Hermitian elements with their fixed-end forces reproduce these exactly at
# the nodes, so the tolerance is round-off.
source [file join [file dirname [info script]] .. lib check.tcl]

set TOL 1e-9
set nEle 4
set L 120.0; set E 29000.0; set A 20.0; set I 800.0
set P 3.0; set w -0.02
set le [expr {$L / $nEle}]
set tip [expr {$nEle + 1}]
model basic -ndm 2 -ndf 3
for {set i 0} {$i <= $nEle} {incr i} { node [expr {$i + 1}] [expr {$le * $i}] 0.0 }
fix 1 1 1 1
geomTransf Linear 1
for {set i 1} {$i <= $nEle} {incr i} { element elasticBeamColumn $i $i [expr {$i + 1}] $A $E $I 1 }
timeSeries Linear 1
pattern Plain 1 1 { load $tip 0.0 $P 0.0 }
file mkdir out
recorder Element -file out/base.out -time -precision 12 -ele 1 localForce
constraints Plain; numberer RCM; system BandGeneral
test NormDispIncr 1e-12 5; algorithm Linear
integrator LoadControl 0.25
analysis Static
checkTrue "four load steps: analyze returns 0" [expr {[analyze 4] == 0}]

# The base element's end forces, the forces its nodes apply to it: at the support -P and -P L,
# at its other end +P and P (L - le).
check "eleForce: base element shear -P" [eleForce 1 2] [expr {-$P}] $TOL
check "eleForce: base element moment at the support -P L" [eleForce 1 3] [expr {-$P * $L}] $TOL
check "eleForce: base element moment at its far end P (L - le)" [eleForce 1 6] \
    [expr {$P * ($L - $le)}] $TOL
check "eleResponse localForce: moment in the tip element -P le" \
    [lindex [eleResponse $nEle localForce] 2] [expr {-$P * $le}] $TOL
reactions
check "reaction: base moment -P L" [nodeReaction 1 3] [expr {-$P * $L}] $TOL
checkTrue "the analysis left the elastic beams to the product (no element update counted)" \
    [expr {[dict get [analysisStatistics] elementUpdates] == 0}]

# A step that fails leaves the model at the last converged state, the beams included.
test NormUnbalance 1e-30 1; algorithm Newton
checkTrue "a step whose test cannot pass fails" [expr {[analyze 1] != 0}]
check "after the failed step: tip deflection P L^3/(3 E I)" [nodeDisp $tip 2] \
    [expr {$P * $L ** 3 / (3.0 * $E * $I)}] $TOL
check "after the failed step: base moment -P L" [eleForce 1 3] [expr {-$P * $L}] $TOL
remove recorders

# The recorder read the base moment at every committed step: -P L times the load factor.
set rows [split [string trim [read [set f [open out/base.out]]]] "\n"]
close $f
checkTrue "the recorder holds the four committed steps" [expr {[llength $rows] == 4}]
set k 0
foreach row $rows {
  incr k
  check "recorder step $k: base moment -P L $k/4" [lindex $row 3] [expr {-$P * $L * $k / 4.0}] $TOL
}

# A member load on every beam: the analysis forms their forces through the beams again (each
# beam's state is brought up to date when the mark is lifted).
loadConst -time 0.0
pattern Plain 2 1 { eleLoad -range 1 $nEle -type -beamUniform $w }
test NormDispIncr 1e-12 5; algorithm Linear
integrator LoadControl 1.0
checkTrue "with the member loads: analyze returns 0" [expr {[analyze 1] == 0}]
check "tip deflection P L^3/(3 E I) + w L^4/(8 E I)" [nodeDisp $tip 2] \
    [expr {$P * $L ** 3 / (3.0 * $E * $I) + $w * $L ** 4 / (8.0 * $E * $I)}] $TOL
check "base moment -(P L + w L^2/2)" [eleForce 1 3] [expr {-($P * $L + $w * $L ** 2 / 2.0)}] $TOL
checkTrue "the loaded beams were updated" \
    [expr {[dict get [analysisStatistics] elementUpdates] > 0}]
wipe
finish
