# SPDX-License-Identifier: MIT
# Bridge case study: dead-load reactions against hand calculation, and the model's
# fundamental longitudinal and transverse periods against an independent isolated-deck estimate.
source [file join [file dirname [info script]] .. lib check.tcl]
set ::bridgeLibraryOnly 1
source [file join [file dirname [info script]] bridge.tcl]

# Tolerances.
# Sum of the vertical reactions = total weight: the loads are nodal, so equilibrium is exact to
# the solver and the convergence tolerance.
set kTotalTol 1e-8
# Each pier: half of each girder resting on it plus its own weight. The girder on two bearings
# is statically determinate except for the bearings' rocking stiffness Kr, which couples the girder
# ends to the pier caps' rotations; that shifts load between the ends by well under 1 %.
set kPierTol 0.01
# Period estimate (below): deck as one rigid mass on every support line's bearing (initial
# stiffness Y0/U0) in series with its pier (cantilever, uncracked fiber segment, cracked elastic
# segments above) and foundation (translation and rocking springs), with the substructure masses
# by a Rayleigh quotient on the static deflected shape. It neglects that the open joints let the
# girders move apart and the rotary inertia: agreement within 10 %.
set kPeriodTol 0.10

buildModel nopound
checkAbs "dead load converges" [applyDeadLoad] 0 0
reactions
set d $::derived
set total 0.0
set hand 0.0
for {set p 1} {$p <= $nSpans + 1} {incr p} {
  set R [nodeReaction [expr {1000 * $p + 1}] 3]
  set total [expr {$total + $R}]
  set H [lindex $pierHeights [expr {$p - 1}]]
  set W [expr {($footingMass + $capMass + [dict get $d pierMass] * $H) * $g}]
  set nGirders [expr {($p > 1) + ($p <= $nSpans)}]
  # girder: from its end face to its end face; half of its weight to each end
  set girderW [expr {$girderMass * ($spanLength - $jointGap) * $g}]
  set Rhand [expr {$W + 0.5 * $nGirders * $girderW}]
  set hand [expr {$hand + $Rhand}]
  check "PC$p vertical reaction = footing + cap + pier + half of each girder (kN)" $R $Rhand $kPierTol
}
check "sum of the vertical reactions = total weight (kN)" $total $hand $kTotalTol

# Periods: eigen at the dead-load state (bearings at their initial stiffness).
set lambda [eigen 6]
set T {}
foreach l $lambda { lappend T [expr {2.0 * $pi / sqrt($l)}] }
puts "model periods (s): [join [lmap t $T {format %.3f $t}] {, }]"
# Independent estimate per support line p (interior piers carry two bearings).
set Y0 [dict get $d Y0]; set U0 [dict get $d U0]
set K0 [expr {$Y0 / $U0}]
set Ig [expr {$pi * pow($pierD, 4) / 64.0}]
set Ec [expr {2.0 * abs($fcCore) / 0.0025}]                ;# Concrete02 initial modulus 2 f'c / eps0
set rs [expr {$pierD / 2.0 - $pierCover - 0.02}]
set EI1 [expr {$Ec * $Ig + (2.0e8 - $Ec) * $nBars * $barArea * $rs * $rs / 2.0}]
set EI2 [expr {$concreteE * $crackedFactor * $Ig}]
set Ktot 0.0
set phis {}
for {set p 1} {$p <= $nSpans + 1} {incr p} {
  set H [expr {[lindex $pierHeights [expr {$p - 1}]] + $bearingHeight}]
  set Lh $hingeLength
  set flexPier [expr {(pow($H, 3) - pow($H - $Lh, 3)) / (3.0 * $EI1) + pow($H - $Lh, 3) / (3.0 * $EI2)}]
  set flexFound [expr {1.0 / [dict get $d kFH] + $H * $H / [dict get $d kFR]}]
  set nB [expr {($p > 1) + ($p <= $nSpans)}]
  set flex [expr {1.0 / ($nB * $K0) + $flexPier + $flexFound}]
  set Ktot [expr {$Ktot + 1.0 / $flex}]
  # static deflected shape under the deck's load (deck = 1): footing and cap displacements
  lappend phis [expr {(1.0 / [dict get $d kFH]) / $flex}] [expr {($flexPier + $flexFound) / $flex}]
}
# Rayleigh quotient with that shape: K = sum of the line stiffnesses, M = deck + substructure
# masses weighted by their squared displacements (pier mass at the mean of footing and cap).
set Mdeck [expr {$nSpans * $girderMass * ($spanLength - $jointGap)}]
set M $Mdeck
set p 0
foreach {pf pc} $phis {
  set H [lindex $pierHeights $p]; incr p
  set M [expr {$M + $footingMass * $pf * $pf + $capMass * $pc * $pc + [dict get $d pierMass] * $H * pow(0.5 * ($pf + $pc), 2)}]
}
set Test [expr {2.0 * $pi * sqrt($M / $Ktot)}]
puts [format "isolated-deck estimate: K = %.0f kN/m, M = %.0f t (deck %.0f t), T = %.3f s" $Ktot $M $Mdeck $Test]
# The longitudinal deck mode: the first mode whose middle-girder motion is mainly along X (the
# modes before it are transverse and roll modes of the girders on their bearings).
set mid [dict get $::girderMid 2]
set Tlong ""
for {set m 1} {$m <= [llength $T] && $Tlong eq ""} {incr m} {
  set ux [expr {abs([nodeEigenvector $mid $m 1])}]
  set uy [expr {abs([nodeEigenvector $mid $m 2])}]
  if {$ux > 2.0 * $uy} { set Tlong [lindex $T [expr {$m - 1}]]; set modeLong $m }
}
checkTrue "a longitudinal deck mode among the first six" [expr {$Tlong ne ""}]
if {$Tlong ne ""} {
  check "longitudinal deck period (mode $modeLong) vs isolated-deck estimate (s)" $Tlong $Test $kPeriodTol
}
finish
