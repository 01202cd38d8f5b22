# SPDX-License-Identifier: MIT
# Newmark's method on Chopra's SDF system under a half-sine pulse.
#
# Source: A. K. Chopra, Dynamics of Structures (4th ed.), Chapter 5:
#   - system of Examples 5.1-5.4: m = 0.2533 kip-s^2/in, k = 10 kip/in (Tn = 1 s), zeta = 5%,
#     p(t) = 10 sin(pi t / 0.6) kips for t <= 0.6 s, 0 after; dt = 0.1 s;
#   - Example 5.2 (central difference): Table 5.3.1, "Central difference method";
#   - Example 5.3 (average acceleration, gamma = 1/2, beta = 1/4) and Example 5.4 (linear
#     acceleration, gamma = 1/2, beta = 1/6): Table 5.4.2, "Newmark's method: linear systems";
#   - Examples 5.5/5.6: the same system, elastic-perfectly-plastic with fy = 7.5 kips, average
#     acceleration with Newton-Raphson iterations: Table 5.7.1, "Newmark's method: nonlinear systems".
# The same system is also run with HHT and generalized-alpha against their recurrences in the
# convention the program documents (OpenSees': the alphas weight the NEW state,
# M a_{n+aM} + C v_{n+aF} + K u_{n+aF} = p(t_n + aF dt), x_{n+a} = (1-a) x_n + a x_{n+1};
# Hilber, Hughes and Taylor, EESD 5 (1977) 283-292; Chung and Hulbert, J. Appl. Mech. 60 (1993)
# 371-375, eqs. 8-10 with alpha_new = 1 - alpha_old).
# Expected values: the recurrences of Tables 5.4.2 and 5.7.1, computed step by step below in Tcl
# (an implementation independent of the program's assembler/integrator), and for the linear system
# the exact solution of the pulse (Chopra eqs. 3.2.1-3.2.4 during the pulse, eq. 2.2.4 free
# vibration after it) against a run with a small step.
source [file join [file dirname [info script]] .. lib check.tcl]

set m 0.2533
set k 10.0
set zeta 0.05
set wn [expr {sqrt($k / $m)}]
set c [expr {2.0 * $zeta * $m * $wn}]
set p0 10.0
set td 0.6
set fy 7.5
set dtBook 0.1
set nBook 20   ;# 2 s: the pulse (6 steps) and 14 steps of free vibration

# Recurrence against the program: the same equations, rounding only.
set TOL_RECURRENCE 1e-9
# Small-step run against the exact solution: average acceleration's period error
# (omega dt)^2/12 ~ 3e-6 at dt = 1 ms, so 1e-4 of the peak leaves margin.
set TOL_EXACT 1e-4

proc pulse {t} {
  if {$t <= $::td + 1e-12} { return [expr {$::p0 * sin(acos(-1.0) * $t / $::td)}] }
  return 0.0
}

# Chopra Table 5.4.2 (linear systems), from rest; returns the list of u_i, i = 1..n.
proc newmarkLinear {gamma beta dt n} {
  set m $::m; set k $::k; set c $::c
  set u 0.0; set v 0.0
  set a [expr {([pulse 0.0] - $c * $v - $k * $u) / $m}]
  set a1 [expr {$m / ($beta * $dt * $dt) + $gamma * $c / ($beta * $dt)}]
  set a2 [expr {$m / ($beta * $dt) + ($gamma / $beta - 1.0) * $c}]
  set a3 [expr {(1.0 / (2.0 * $beta) - 1.0) * $m + $dt * ($gamma / (2.0 * $beta) - 1.0) * $c}]
  set khat [expr {$k + $a1}]
  set out {}
  for {set i 1} {$i <= $n} {incr i} {
    set phat [expr {[pulse [expr {$i * $dt}]] + $a1 * $u + $a2 * $v + $a3 * $a}]
    set un [expr {$phat / $khat}]
    set vn [expr {$gamma / ($beta * $dt) * ($un - $u) + (1.0 - $gamma / $beta) * $v
                  + $dt * (1.0 - $gamma / (2.0 * $beta)) * $a}]
    set an [expr {($un - $u) / ($beta * $dt * $dt) - $v / ($beta * $dt) - (1.0 / (2.0 * $beta) - 1.0) * $a}]
    set u $un; set v $vn; set a $an
    lappend out $u
  }
  return $out
}

# Chopra Table 5.3.1 (central difference), from rest; returns the list of u_i, i = 1..n.
proc centralDifference {dt n} {
  set m $::m; set k $::k; set c $::c
  set u0 0.0; set v0 0.0
  set a0 [expr {([pulse 0.0] - $c * $v0 - $k * $u0) / $m}]
  set uPrev [expr {$u0 - $dt * $v0 + $dt * $dt / 2.0 * $a0}]
  set khat [expr {$m / ($dt * $dt) + $c / (2.0 * $dt)}]
  set a [expr {$m / ($dt * $dt) - $c / (2.0 * $dt)}]
  set b [expr {$k - 2.0 * $m / ($dt * $dt)}]
  set u $u0
  set out {}
  for {set i 0} {$i < $n} {incr i} {
    set phat [expr {[pulse [expr {$i * $dt}]] - $a * $uPrev - $b * $u}]
    set uPrev $u
    set u [expr {$phat / $khat}]
    lappend out $u
  }
  return $out
}

# Generalized-alpha recurrence (linear system, from rest), OpenSees weighting of the new state.
proc generalizedAlpha {aM aF gamma beta dt n} {
  set m $::m; set k $::k; set c $::c
  set u 0.0; set v 0.0
  set a [expr {([pulse 0.0] - $c * $v - $k * $u) / $m}]
  set c1 [expr {1.0 / ($beta * $dt * $dt)}]
  set out {}
  for {set i 0} {$i < $n} {incr i} {
    set ut [expr {$u + $dt * $v + $dt * $dt * (0.5 - $beta) * $a}]
    set vt [expr {$v + $dt * (1.0 - $gamma) * $a}]
    set lhs [expr {$m * $aM * $c1 + $c * $aF * $gamma * $dt * $c1 + $k * $aF}]
    set rhs [expr {[pulse [expr {($i + $aF) * $dt}]] - $m * (1.0 - $aM) * $a + $m * $aM * $c1 * $ut
                   - $c * (1.0 - $aF) * $v - $c * $aF * ($vt - $gamma * $dt * $c1 * $ut) - $k * (1.0 - $aF) * $u}]
    set un [expr {$rhs / $lhs}]
    set an [expr {$c1 * ($un - $ut)}]
    set vn [expr {$vt + $gamma * $dt * $an}]
    set u $un; set v $vn; set a $an
    lappend out $u
  }
  return $out
}

# Elastic-perfectly-plastic spring: force and tangent at trial u from the committed plastic
# displacement up (Chopra Fig. 5.7.1 / §5.7).
proc epp {u up} {
  set f [expr {$::k * ($u - $up)}]
  if {$f > $::fy} { return [list $::fy 0.0] }
  if {$f < -$::fy} { return [list [expr {-$::fy}] 0.0] }
  return [list $f $::k]
}

# Chopra Table 5.7.1 (nonlinear systems, Newton-Raphson iteration), from rest.
proc newmarkEpp {gamma beta dt n} {
  set m $::m; set c $::c
  set u 0.0; set v 0.0; set up 0.0
  lassign [epp $u $up] fs kT
  set a [expr {([pulse 0.0] - $c * $v - $fs) / $m}]
  set a1 [expr {$m / ($beta * $dt * $dt) + $gamma * $c / ($beta * $dt)}]
  set a2 [expr {$m / ($beta * $dt) + ($gamma / $beta - 1.0) * $c}]
  set a3 [expr {(1.0 / (2.0 * $beta) - 1.0) * $m + $dt * ($gamma / (2.0 * $beta) - 1.0) * $c}]
  set out {}
  for {set i 1} {$i <= $n} {incr i} {
    set phat [expr {[pulse [expr {$i * $dt}]] + $a1 * $u + $a2 * $v + $a3 * $a}]
    set uj $u
    for {set j 0} {$j < 100} {incr j} {
      lassign [epp $uj $up] fs kT
      set R [expr {$phat - $fs - $a1 * $uj}]
      if {abs($R) < 1e-13 * $::fy} break
      set uj [expr {$uj + $R / ($kT + $a1)}]
    }
    # commit: new plastic displacement
    lassign [epp $uj $up] fs kT
    set up [expr {$uj - $fs / $::k}]
    set vn [expr {$gamma / ($beta * $dt) * ($uj - $u) + (1.0 - $gamma / $beta) * $v
                  + $dt * (1.0 - $gamma / (2.0 * $beta)) * $a}]
    set an [expr {($uj - $u) / ($beta * $dt * $dt) - $v / ($beta * $dt) - (1.0 / (2.0 * $beta) - 1.0) * $a}]
    set u $uj; set v $vn; set a $an
    lappend out $u
  }
  return $out
}

# Exact response from rest (Chopra eqs. 3.2.1-3.2.4 with the initial conditions solved for
# A and B; after the pulse, damped free vibration, Chopra eq. 2.2.4).
proc exactPulse {t} {
  set m $::m; set k $::k; set z $::zeta; set wn $::wn
  set w [expr {acos(-1.0) / $::td}]
  set wd [expr {$wn * sqrt(1.0 - $z * $z)}]
  set b [expr {$w / $wn}]
  set den [expr {(1.0 - $b * $b) ** 2 + (2.0 * $z * $b) ** 2}]
  set C [expr {$::p0 / $k * (1.0 - $b * $b) / $den}]
  set D [expr {$::p0 / $k * (-2.0 * $z * $b) / $den}]
  set A [expr {-$D}]
  set B [expr {($z * $wn * $A - $C * $w) / $wd}]
  set tt [expr {min($t, $::td)}]
  set e [expr {exp(-$z * $wn * $tt)}]
  set u [expr {$e * ($A * cos($wd * $tt) + $B * sin($wd * $tt)) + $C * sin($w * $tt) + $D * cos($w * $tt)}]
  if {$t <= $::td} { return $u }
  set v [expr {$e * (-$z * $wn * ($A * cos($wd * $tt) + $B * sin($wd * $tt))
                     + $wd * (-$A * sin($wd * $tt) + $B * cos($wd * $tt)))
               + $C * $w * cos($w * $tt) - $D * $w * sin($w * $tt)}]
  set s [expr {$t - $::td}]
  return [expr {exp(-$z * $wn * $s) * ($u * cos($wd * $s) + ($v + $z * $wn * $u) / $wd * sin($wd * $s))}]
}

# The same system in the program; spring is Elastic, ElasticPP or Steel01 (b = 0).
proc runProgram {spring gamma beta dt n {algo Newton}} {
  wipe
  model basic -ndm 1 -ndf 1
  node 1 0.0
  node 2 0.0 -mass $::m
  fix 1 1
  switch $spring {
    Elastic   { uniaxialMaterial Elastic 1 $::k }
    ElasticPP { uniaxialMaterial ElasticPP 1 $::k [expr {$::fy / $::k}] }
    Steel01   { uniaxialMaterial Steel01 1 $::fy $::k 0.0 }
  }
  uniaxialMaterial Viscous 2 $::c 1.0
  element zeroLength 1 1 2 -mat 1 -dir 1
  element zeroLength 2 1 2 -mat 2 -dir 1
  # p(t) = p0 sin(2 pi t / (2 td)) on [0, td]
  timeSeries Trig 1 0.0 $::td [expr {2.0 * $::td}] -factor $::p0
  pattern Plain 1 1 { load 2 1.0 }
  constraints Plain
  numberer Plain
  system BandGeneral
  test NormDispIncr 1e-14 50
  algorithm {*}$algo
  switch -- $gamma {
    central { integrator CentralDifference }
    HHT     { integrator HHT {*}$beta }
    GenAlpha { integrator GeneralizedAlpha {*}$beta }
    default { integrator Newmark $gamma $beta }
  }
  analysis Transient
  set out {}
  for {set i 1} {$i <= $n} {incr i} {
    set rc [analyze 1 $dt]
    if {$rc != 0} { error "$spring: analyze failed at step $i (code $rc)" }
    lappend out [nodeDisp 2 1]
  }
  return $out
}

proc compareHistories {label got expected tol} {
  set peak 0.0
  foreach e $expected { set peak [expr {max($peak, abs($e))}] }
  set worst 0.0; set at 0; set i 0
  foreach g $got e $expected {
    set err [expr {abs($g - $e) / $peak}]
    if {$err > $worst} { set worst $err; set at $i }
    incr i
  }
  checkAbs "$label: max |u - u_ref| / peak (worst step [expr {$at + 1}])" $worst 0.0 $tol
  # one value printed in full for the reader
  check "$label: u at t = [expr {[llength $got] * $::dtBook}] s (last step)" [lindex $got end] [lindex $expected end] [expr {$tol * 10}]
}

# --- Example 5.2: central difference (Table 5.3.1); dt/Tn = 0.1 < 1/pi, stable ---
set ref [centralDifference $dtBook $nBook]
set got [runProgram Elastic central {} $dtBook $nBook Linear]
compareHistories "Chopra Ex. 5.2 central difference vs Table 5.3.1" $got $ref $TOL_RECURRENCE

# --- Example 5.3: average acceleration (Table 5.4.2) ---
set ref [newmarkLinear 0.5 0.25 $dtBook $nBook]
set got [runProgram Elastic 0.5 0.25 $dtBook $nBook]
compareHistories "Chopra Ex. 5.3 average acceleration vs Table 5.4.2" $got $ref $TOL_RECURRENCE
# peak of the pulse response from Chopra's own example: u reaches its maximum at t = 0.5-0.6 s;
# the peak of the Table 5.4.2 history must be the program's peak
set pk 0.0; foreach u $got { set pk [expr {max($pk, abs($u))}] }
set pr 0.0; foreach u $ref { set pr [expr {max($pr, abs($u))}] }
check "Chopra Ex. 5.3 peak |u| vs Table 5.4.2" $pk $pr $TOL_RECURRENCE

# --- Example 5.4: linear acceleration (Table 5.4.2 with beta = 1/6) ---
set ref [newmarkLinear 0.5 [expr {1.0 / 6.0}] $dtBook $nBook]
set got [runProgram Elastic 0.5 [expr {1.0 / 6.0}] $dtBook $nBook]
compareHistories "Chopra Ex. 5.4 linear acceleration vs Table 5.4.2" $got $ref $TOL_RECURRENCE

# --- HHT (alpha = 0.9: gamma = 1.5 - alpha, beta = (2 - alpha)^2/4) ---
set alpha 0.9
set ref [generalizedAlpha 1.0 $alpha [expr {1.5 - $alpha}] [expr {(2.0 - $alpha) ** 2 / 4.0}] $dtBook $nBook]
set got [runProgram Elastic HHT $alpha $dtBook $nBook]
compareHistories "HHT alpha=0.9 (Hilber-Hughes-Taylor 1977, OpenSees weighting)" $got $ref $TOL_RECURRENCE
# --- generalized-alpha, rho_inf = 0.8: aM = (2 - rho)/(1 + rho), aF = 1/(1 + rho) ---
set rho 0.8
set aM [expr {(2.0 - $rho) / (1.0 + $rho)}]
set aF [expr {1.0 / (1.0 + $rho)}]
set gam [expr {0.5 + $aM - $aF}]
set bet [expr {0.25 * (1.0 + $aM - $aF) ** 2}]
set ref [generalizedAlpha $aM $aF $gam $bet $dtBook $nBook]
set got [runProgram Elastic GenAlpha [list $aM $aF] $dtBook $nBook]
compareHistories "generalized-alpha rho_inf=0.8 (Chung-Hulbert 1993, OpenSees weighting)" $got $ref $TOL_RECURRENCE

# --- Exact solution (Chopra eqs. 3.2.x, 2.2.4) with a small step ---
set dtSmall 0.001
set nSmall 2000
set got [runProgram Elastic 0.5 0.25 $dtSmall $nSmall]
set exact {}
set sampled {}
for {set i 1} {$i <= $nSmall} {incr i} {
  if {$i % 100 == 0} {
    lappend exact [exactPulse [expr {$i * $dtSmall}]]
    lappend sampled [lindex $got [expr {$i - 1}]]
  }
}
set peak 0.0; foreach e $exact { set peak [expr {max($peak, abs($e))}] }
set worst 0.0
foreach g $sampled e $exact { set worst [expr {max($worst, abs($g - $e) / $peak)}] }
checkAbs "half-sine pulse, exact (Chopra eqs. 3.2.1-3.2.4, 2.2.4), dt=1ms: max err/peak" $worst 0.0 $TOL_EXACT

# --- Examples 5.5/5.6: elastic-perfectly-plastic, fy = 7.5 kips (Table 5.7.1) ---
set ref [newmarkEpp 0.5 0.25 $dtBook $nBook]
set yielded 0
foreach u $ref { if {$k * abs($u) > $fy} { set yielded 1 } }
checkTrue "Chopra Ex. 5.5: the reference history yields (k |u| > fy somewhere)" $yielded
set got [runProgram ElasticPP 0.5 0.25 $dtBook $nBook]
compareHistories "Chopra Ex. 5.5 EPP (ElasticPP) vs Table 5.7.1" $got $ref $TOL_RECURRENCE
set got [runProgram Steel01 0.5 0.25 $dtBook $nBook]
compareHistories "Chopra Ex. 5.5 EPP (Steel01 b=0) vs Table 5.7.1" $got $ref $TOL_RECURRENCE
# Example 5.6 uses modified Newton-Raphson (tangent of the step's start); the converged answer is
# the same.
set got [runProgram ElasticPP 0.5 0.25 $dtBook $nBook ModifiedNewton]
compareHistories "Chopra Ex. 5.6 EPP, ModifiedNewton vs Table 5.7.1" $got $ref $TOL_RECURRENCE
set got [runProgram ElasticPP 0.5 0.25 $dtBook $nBook {ModifiedNewton -initial}]
compareHistories "Chopra Ex. 5.6 EPP, ModifiedNewton -initial vs Table 5.7.1" $got $ref $TOL_RECURRENCE
wipe

finish
