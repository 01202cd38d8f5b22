# SPDX-License-Identifier: MIT
# Oblique impact with friction on a fixed target face (hard case 2).
# Closed forms (rigid-body impact with Coulomb friction): the normal velocity reverses by the
# restitution, dv_n = (1 + e_eff) v_n (e_eff: no-tension restitution, lib/contact.tcl), and while
# the contactor slides the tangential velocity drops by mu dv_n = mu (1 + e_eff) |v_n| (the
# min(|v_t|, mu (1 + e)|v_n|) law when mu (1 + e)|v_n| < |v_t|). Runs with Newton on the
# non-symmetric sliding tangent (system FullGeneral).
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] lib contact.tcl]

set K 1.0e6
set m 2.0
set mu 0.3

# Fixed face 1-2-3-4 (normal +z), contactor 5 of mass m launched with (vt, 0, -vn) by a pulse.
# Returns {vt0 vn0 vt1 vn1 failed} (velocities before and after the impact).
proc oblique {e et vt vn n} {
  global K m mu
  wipe
  model basic -ndm 3 -ndf 3
  node 1 -2 -2 0; node 2 2 -2 0; node 3 2 2 0; node 4 -2 2 0
  node 5 -1.5 0 0.01
  foreach t {1 2 3 4} { fix $t 1 1 1 }
  fix 5 0 1 0
  mass 5 $m $m $m
  element nodeToSurface 1 5 1 2 3 4 -K $K -e $e -et $et -mu_s $mu -mu_k $mu -masses $m 1e12
  set Tc [expr {$::pi*sqrt($m/$K)}]
  set dt [expr {$Tc/$n}]
  set tp [expr {ceil(0.002/$dt)*$dt}]
  timeSeries Constant 1
  pattern Plain 1 1 { load 5 [expr {$m*$vt/$tp}] 0 [expr {-$m*$vn/$tp}] }
  constraints Plain; numberer Plain; system FullGeneral
  test NormDispIncr 1e-12 50; algorithm Newton
  integrator Newmark 0.5 0.25; analysis Transient
  set failed [runUntil $dt $tp]
  remove loadPattern 1
  incr failed [runUntil $dt [expr {$tp + $dt}]]
  set vt0 [nodeVel 5 1]; set vn0 [expr {-[nodeVel 5 3]}]
  incr failed [runUntil $dt [expr {$tp + 0.05}] {expr {[lindex [eleResponse 1 impulse] 0] > 0 && [lindex [eleResponse 1 gap] 0] > 0}}]
  return [list $vt0 $vn0 [nodeVel 5 1] [nodeVel 5 3] $failed]
}

# 1. Elastic (e = 1) and sliding from first touch: dv_t = mu dv_n to solver precision.
foreach n {20 80} {
  lassign [oblique 1.0 1.0 2.0 1.0 $n] vt0 vn0 vt1 vn1 failed
  checkTrue "e=1 n=$n: every step converged" [expr {$failed == 0}]
  set dvn [expr {$vn1 + $vn0}]
  set dvt [expr {$vt0 - $vt1}]
  set wdt [expr {$::pi/$n}]
  check "e=1 n=$n: normal speed reverses, dv_n = 2 v_n" $dvn [expr {2*$vn0}] [expr {0.5*$wdt*$wdt}]
  # The release step carries a small normal force without friction (see NodeToSurfaceContact3d.h):
  # an impulse of at most N dt, N <= K v_n dt, i.e. a relative error <= (w dt)^2.
  check "e=1 n=$n: dv_t = min(v_t, mu dv_n) = mu dv_n" $dvt [expr {min($vt0, $mu*$dvn)}] [expr {$wdt*$wdt}]
}

# 2. e = 0.5: the dashpot force C v_n at first touch makes the contactor stick for
# t_s ~ mu C v_n / (K v_t), so dv_t falls short of mu dv_n by at most mu^2 4 xi^2 v_n^2 / v_t.
set e 0.5
set xi [dampingRatio $e]
set eEff [effectiveRestitution $xi]
lassign [oblique $e 1.0 2.0 1.0 80] vt0 vn0 vt1 vn1 failed
checkTrue "e=0.5: every step converged" [expr {$failed == 0}]
set dvn [expr {$vn1 + $vn0}]
set dvt [expr {$vt0 - $vt1}]
set wdt [expr {$::pi/80}]
checkAbs "e=0.5: dv_n = (1 + e_eff) v_n, e_eff = [format %.5f $eEff]" [expr {$dvn/$vn0}] [expr {1 + $eEff}] \
    [expr {0.5*$wdt*$wdt + $xi*$wdt}]
checkAbs "e=0.5: dv_t = mu dv_n (stick at touch: within mu^2 4 xi^2 v_n^2/v_t)" $dvt [expr {$mu*$dvn}] \
    [expr {$mu*$mu*4*$xi*$xi*$vn0*$vn0/$vt0}]

# 3. v_t < mu v_n: the contactor sticks through the impact. The rigid-body law would stop the
# tangential motion (dv_t = v_t); in this model the stick spring (Kt = K, same period as the
# normal spring) returns it with the tangential restitution: et = 1 gives dv_t = 2 v_t exactly
# in the limit, and a fully damped tangent (et -> 0) less than that.
lassign [oblique 1.0 1.0 0.05 1.0 80] vt0 vn0 vt1 vn1 failed
checkTrue "stick: every step converged" [expr {$failed == 0}]
check "stick, et=1: dv_t = 2 v_t (elastic tangential rebound)" [expr {$vt0 - $vt1}] [expr {2*$vt0}] 1e-2
finish
