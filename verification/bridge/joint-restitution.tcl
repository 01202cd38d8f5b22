# SPDX-License-Identifier: MIT
# A flat impact across one of the case study's joints, for each impact law (verification).
#
#   dabs verification/bridge/joint-restitution.tcl
#
# Two spans of the case study (bridge.tcl's masses, end faces and pounding, jointPounding with
# its laws' arguments, impactLawArgs) meet head-on at the relative speed impactSpeedRef, free of
# bearings, piers and gravity. The eight pairs of the joint share one flat impact, so the joint
# must behave as the law written for the whole joint: two bodies of the spans' masses on one
# spring-dashpot of stiffness EA/L (kelvin), or on k_h delta^1.5 with the law's damping. The
# expected exit/approach speed ratio comes from a fourth-order Runge-Kutta integration, in this
# script, of the scalar equation m x'' = -N(x, x') with the whole joint's law written from its
# papers (m = M1 M2 / (M1 + M2)); for kelvin it is also the closed form of a spring-dashpot that
# cannot pull (lib/contact.tcl), and for the power laws the peak penetration of the elastic law
# equals the Kelvin spring's, v sqrt(m / (EA/L)), as the laws' k_h is chosen (bridge.tcl).
# Checks that the pairs take their share of the masses: with the whole masses on every pair the
# eight dashpots would damp sqrt(8) times as much (an exit ratio of 0.38 for e = 0.65).
set here [file dirname [file normalize [info script]]]
set ::bridgeLibraryOnly 1
source [file join $here bridge.tcl]
source [file join $here .. lib check.tcl]
source [file join $here .. pounding lib contact.tcl]

set M [expr {$girderMass * $spanLength}]     ;# t, each body (a span)
set mred [expr {0.5 * $M}]
set Ktotal [expr {$steelE * $girderA / $spanLength}]
set v $impactSpeedRef
set deltaKelvin [expr {$v * sqrt($mred / $Ktotal)}]
set kh [expr {1.25 * $Ktotal / sqrt($deltaKelvin)}]   ;# whole joint, the design rule of bridge.tcl

# The whole joint's normal force at penetration x >= 0 and its rate xd (> 0 approaching).
proc jointForce {law x xd} {
  global Ktotal kh mred restitution v
  switch -- $law {
    kelvin {
      set xi [dampingRatio $restitution]
      return [expr {max(0.0, $Ktotal * $x + 2.0 * $xi * sqrt($Ktotal * $mred) * $xd)}]
    }
    hertz { return [expr {$kh * pow($x, 1.5)}] }
    hertzdamp {
      # Muthukumar and DesRoches (2006) with Lankarani and Nikravesh's (1990) c_h
      set ch [expr {3.0 * $kh * (1.0 - $restitution * $restitution) / (4.0 * $v)}]
      return [expr {max(0.0, $kh * pow($x, 1.5) + $ch * pow($x, 1.5) * $xd)}]
    }
    jankowski {
      # Jankowski (2005): damping while approaching only; xi(e) of Jankowski (2006, eq. 17)
      set e $restitution
      set xi [expr {9.0 * sqrt(5.0) * (1.0 - $e * $e) / (2.0 * $e * ($e * (9.0 * acos(-1.0) - 16.0) + 16.0))}]
      set c [expr {$xd > 0.0 ? 2.0 * $xi * sqrt($kh * sqrt($x) * $mred) : 0.0}]
      return [expr {$kh * pow($x, 1.5) + $c * $xd}]
    }
  }
}

# Exit/approach speed ratio and peak penetration of the scalar impact (RK4, 20000 steps over the
# Kelvin spring's half period).
proc referenceImpact {law} {
  global v mred Ktotal
  set h [expr {acos(-1.0) * sqrt($mred / $Ktotal) / 20000.0}]
  set x 0.0; set xd $v; set peak 0.0
  for {set i 0} {$i < 1000000} {incr i} {
    set a1 [expr {-[jointForce $law [expr {max($x, 0.0)}] $xd] / $mred}]
    set x2 [expr {$x + 0.5 * $h * $xd}]; set v2 [expr {$xd + 0.5 * $h * $a1}]
    set a2 [expr {-[jointForce $law [expr {max($x2, 0.0)}] $v2] / $mred}]
    set x3 [expr {$x + 0.5 * $h * $v2}]; set v3 [expr {$xd + 0.5 * $h * $a2}]
    set a3 [expr {-[jointForce $law [expr {max($x3, 0.0)}] $v3] / $mred}]
    set x4 [expr {$x + $h * $v3}]; set v4 [expr {$xd + $h * $a3}]
    set a4 [expr {-[jointForce $law [expr {max($x4, 0.0)}] $v4] / $mred}]
    set xn [expr {$x + $h / 6.0 * ($xd + 2.0 * $v2 + 2.0 * $v3 + $v4)}]
    set vn [expr {$xd + $h / 6.0 * ($a1 + 2.0 * $a2 + 2.0 * $a3 + $a4)}]
    set peak [expr {max($peak, $xn)}]
    if {$xn < 0.0 && $vn < 0.0} { return [list [expr {-$vn / $v}] $peak] }
    set x $xn; set xd $vn
  }
  error "referenceImpact $law: no separation"
}

# The largest penetration over the pairs so far, in ::peakNow (runUntil's test after each step).
proc track {pairs} {
  foreach p $pairs { set ::peakNow [expr {max($::peakNow, -[lindex [eleResponse $p gap] 0])}] }
  return 0
}

# The joint through the program: two span bodies (a node each, free along X only) with the
# case study's end faces and pounding; returns {exit ratio, peak penetration, failed steps}.
proc programImpact {law} {
  global M v mred Ktotal
  set ::impactLaw $law
  wipe
  model basic -ndm 3 -ndf 6
  set left 10000; set right 20000
  node $left [expr {-0.5 * $::spanLength}] 0 0
  node $right [expr {0.5 * $::spanLength}] 0 0
  foreach n [list $left $right] { fix $n 0 1 1 1 1 1; mass $n $M 0 0 0 0 0 }
  endFace $left 70 -0.01 $left 0.0
  endFace $right 60 0.01 $right 0.0
  set pairs [jointPounding 500 $left $right $M $M [expr {$Ktotal / 8.0}]]
  set dt [expr {acos(-1.0) * sqrt($mred / $Ktotal) / 400.0}]
  set tp [expr {10 * $dt}]
  timeSeries Constant 1
  pattern Plain 1 1 {
    load $left [expr {0.5 * $M * $v / $tp}] 0 0 0 0 0
    load $right [expr {-0.5 * $M * $v / $tp}] 0 0 0 0 0
  }
  constraints Transformation; numberer Plain; system FullGeneral
  test NormDispIncr 1e-12 50; algorithm Newton
  integrator Newmark 0.5 0.25; analysis Transient
  set failed [runUntil $dt $tp]
  remove loadPattern 1
  incr failed [runUntil $dt [expr {$tp + $dt}]]
  set approach [expr {[nodeVel $left 1] - [nodeVel $right 1]}]
  set ::peakNow 0.0
  incr failed [runUntil $dt 0.2 [list track $pairs]]
  set ratio [expr {-([nodeVel $left 1] - [nodeVel $right 1]) / $approach}]
  return [list $ratio $::peakNow $failed]
}

foreach law {kelvin hertz hertzdamp jankowski} {
  lassign [referenceImpact $law] refRatio refPeak
  lassign [programImpact $law] ratio peak failed
  puts [format "%-9s exit ratio %.4f (reference %.4f), peak penetration %.5f m (reference %.5f)" \
      $law $ratio $refRatio $peak $refPeak]
  checkTrue "$law: every step converged" [expr {$failed == 0}]
  # 400 steps per Kelvin half period: Newmark's error is below 1e-3 for these smooth laws
  checkAbs "$law: exit/approach ratio = the whole joint's law (RK4)" $ratio $refRatio 0.01
  check "$law: peak penetration = the whole joint's law (RK4)" $peak $refPeak 0.01
}
# The closed forms behind the reference: the no-tension Kelvin restitution, the elastic laws'
# equal peak penetration, and Jankowski's restitution close to e.
checkAbs "kelvin reference = no-tension e_eff(xi(e))" [lindex [referenceImpact kelvin] 0] \
    [effectiveRestitution [dampingRatio $restitution]] 1e-4
check "hertz peak penetration = Kelvin spring's v sqrt(m/K)" [lindex [referenceImpact hertz] 1] $deltaKelvin 1e-3
checkAbs "hertz reference restitution = 1" [lindex [referenceImpact hertz] 0] 1.0 1e-6
checkAbs "jankowski reference restitution within 0.01 of e" [lindex [referenceImpact jankowski] 0] $restitution 0.01
finish
