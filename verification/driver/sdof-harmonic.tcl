# SPDX-License-Identifier: MIT
# SDF system under a harmonic force p0 sin(w t), starting from rest.
#
# Source: A. K. Chopra, Dynamics of Structures (4th ed.), §3.1-3.2:
#   undamped, eq. 3.1.6: u(t) = p0/k / (1 - b^2) (sin w t - b sin wn t), b = w/wn;
#   damped, eqs. 3.2.1-3.2.4: u(t) = e^(-zeta wn t)(A cos wD t + B sin wD t) + C sin w t + D cos w t,
#   C = p0/k (1 - b^2)/den, D = p0/k (-2 zeta b)/den, den = (1 - b^2)^2 + (2 zeta b)^2,
#   with A, B from u(0) = 0 and u'(0) = 0.
# Newmark's average acceleration is second order (Chopra §5.5, period error (wn dt)^2/12): halving
# dt divides the error by about 4.
source [file join [file dirname [info script]] .. lib check.tcl]

set m 2.0
set k 800.0          ;# wn = 20 rad/s, Tn = 0.314 s
set p0 50.0
set w 13.0           ;# b = 0.65
set tEnd 1.5         ;# about 5 natural periods
set wn [expr {sqrt($k / $m)}]
set Tn [expr {2.0 * acos(-1.0) / $wn}]

# The response must match the closed form to this fraction of its peak at dt = Tn/400
# (phase error after 5 periods: 5 * 2 pi (wn dt)^2 / 12 ~ 6e-4).
set TOL_CLOSED_FORM 2e-3
# Error ratio between dt and dt/2 for a second-order method.
set RATIO_EXPECTED 4.0
set TOL_RATIO 0.1

proc exact {zeta t} {
  set wn $::wn; set w $::w; set k $::k; set p0 $::p0
  set b [expr {$w / $wn}]
  if {$zeta == 0.0} {
    return [expr {$p0 / $k / (1.0 - $b * $b) * (sin($w * $t) - $b * sin($wn * $t))}]
  }
  set wd [expr {$wn * sqrt(1.0 - $zeta * $zeta)}]
  set den [expr {(1.0 - $b * $b) ** 2 + (2.0 * $zeta * $b) ** 2}]
  set C [expr {$p0 / $k * (1.0 - $b * $b) / $den}]
  set D [expr {$p0 / $k * (-2.0 * $zeta * $b) / $den}]
  set A [expr {-$D}]
  set B [expr {($zeta * $wn * $A - $C * $w) / $wd}]
  return [expr {exp(-$zeta * $wn * $t) * ($A * cos($wd * $t) + $B * sin($wd * $t))
                + $C * sin($w * $t) + $D * cos($w * $t)}]
}

# Max |u - exact| over the history, and the peak of exact, for one run.
# damping: "viscous" (a Viscous zeroLength dashpot, c = 2 zeta m wn), "rayleighM" (rayleigh with
# alphaM = 2 zeta wn) or "rayleighK" (rayleigh with betaK = 2 zeta / wn, on a zeroLength with
# -doRayleigh 1) or "modal" (eigen 1; modalDamping zeta): the same c. "rayleighKoff": betaK on a zeroLength without -doRayleigh, which
# (OpenSees default for zeroLength) gets no stiffness-proportional damping: undamped response
# (betaK = 2 * 0.05 / wn whatever zeta is passed).
proc run {zeta dt {damping viscous}} {
  wipe
  model basic -ndm 1 -ndf 1
  node 1 0.0
  node 2 0.0 -mass $::m
  fix 1 1
  uniaxialMaterial Elastic 1 $::k
  if {$damping eq "rayleighK"} {
    element zeroLength 1 1 2 -mat 1 -dir 1 -doRayleigh 1
  } else {
    element zeroLength 1 1 2 -mat 1 -dir 1
  }
  if {$zeta > 0.0 && $damping eq "viscous"} {
    uniaxialMaterial Viscous 2 [expr {2.0 * $zeta * $::m * $::wn}] 1.0
    element zeroLength 2 1 2 -mat 2 -dir 1
  }
  if {$damping eq "rayleighM"} { rayleigh [expr {2.0 * $zeta * $::wn}] 0.0 0.0 0.0 }
  if {$damping eq "rayleighK"} { rayleigh 0.0 [expr {2.0 * $zeta / $::wn}] 0.0 0.0 }
  if {$damping eq "modal"} { eigen 1; modalDamping $zeta }
  if {$damping eq "rayleighKoff"} { rayleigh 0.0 [expr {2.0 * 0.05 / $::wn}] 0.0 0.0 }
  timeSeries Trig 1 0.0 1.0e6 [expr {2.0 * acos(-1.0) / $::w}] -factor $::p0
  pattern Plain 1 1 { load 2 1.0 }
  constraints Plain
  numberer Plain
  system BandGeneral
  test NormDispIncr 1e-12 10
  algorithm Linear
  integrator Newmark 0.5 0.25
  analysis Transient
  set n [expr {int(round($::tEnd / $dt))}]
  set worst 0.0; set peak 0.0
  for {set i 1} {$i <= $n} {incr i} {
    if {[analyze 1 $dt] != 0} { error "analyze failed at step $i" }
    set e [exact $zeta [getTime %.17g]]
    set peak [expr {max($peak, abs($e))}]
    set worst [expr {max($worst, abs([nodeDisp 2 1] - $e))}]
  }
  return [list $worst $peak]
}

foreach zeta {0.0 0.05} {
  set dt1 [expr {$Tn / 200.0}]
  set dt2 [expr {$dt1 / 2.0}]
  lassign [run $zeta $dt1] e1 peak
  lassign [run $zeta $dt2] e2 peak
  checkAbs "Chopra eq. [expr {$zeta == 0 ? {3.1.6 undamped} : {3.2.x damped zeta=0.05}}], dt=Tn/400: max err/peak" \
    [expr {$e2 / $peak}] 0.0 $TOL_CLOSED_FORM
  check "Newmark average acceleration 2nd order (Chopra §5.5), zeta=$zeta: err(dt)/err(dt/2)" \
    [expr {$e1 / $e2}] $RATIO_EXPECTED $TOL_RATIO
}
foreach damping {rayleighM rayleighK modal} {
  set e [run 0.05 [expr {$Tn / 400.0}] $damping]
  checkAbs "Chopra eq. 3.2.x damped zeta=0.05 with $damping damping, dt=Tn/400: max err/peak" \
    [expr {[lindex $e 0] / [lindex $e 1]}] 0.0 $TOL_CLOSED_FORM
}
# zeroLength without -doRayleigh: no stiffness-proportional damping, so the undamped closed form
set e0 [run 0.0 [expr {$Tn / 400.0}] viscous]
set e1 [run 0.0 [expr {$Tn / 400.0}] rayleighKoff]
checkAbs "zeroLength without -doRayleigh ignores betaK: same error as undamped run (/peak)" \
  [expr {abs([lindex $e1 0] - [lindex $e0 0]) / [lindex $e0 1]}] 0.0 1e-12
# the closed form at one time, printed for the reader (undamped, t = 1.5 s)
set got [lindex [run 0.0 [expr {$Tn / 2000.0}]] 0]
checkAbs "Chopra eq. 3.1.6 at dt=Tn/2000: max |u - exact| (in units of p0/k)" [expr {$got / ($p0 / $k)}] 0.0 1e-4
wipe
finish
