# SPDX-License-Identifier: MIT
# Static LoadControl and DisplacementControl on a system of parallel elastic-plastic springs.
#
# Source (closed form): three springs in parallel between a fixed node and a free node,
# zeroLength elements: spring 1 elastic-perfectly-plastic (k1, fy1), spring 2 elastic-perfectly-
# plastic (k2, fy2), spring 3 elastic (k3). Along a monotone segment that starts at u0 with spring
# forces f0, an EPP spring carries f = clamp(f0 + k (u - u0), -fy, fy) (Chopra, Dynamics of
# Structures, §7.1 and Fig. 7.1.2 elastoplastic idealisation); the load factor equals the sum of
# the spring forces. Loading path: LoadControl to P1 beyond both yield points, LoadControl back to
# zero (elastic unloading with k1 + k2 + k3), DisplacementControl to -0.4 (reverse yielding) and
# back to +0.1. Finally a pure EPP spring pushed by LoadControl past fy: the step fails
# (analyze returns a negative code, no Tcl error) and the model stays at the last converged step.
source [file join [file dirname [info script]] .. lib check.tcl]

set TOL 1e-9
set k1 100.0; set fy1 5.0
set k2 50.0;  set fy2 6.0
set k3 10.0

# closed-form path: committed state (u, f1, f2) at the start of the current monotone segment
set seg [list 0.0 0.0 0.0]
proc clamp {x lim} { expr {max(-$lim, min($lim, $x))} }
proc springForces {u} {
  lassign $::seg u0 f10 f20
  list [clamp [expr {$f10 + $::k1 * ($u - $u0)}] $::fy1] [clamp [expr {$f20 + $::k2 * ($u - $u0)}] $::fy2] \
       [expr {$::k3 * $u}]
}
proc force {u} { tcl::mathop::+ {*}[springForces $u] }
proc newSegment {u} { lassign [springForces $u] f1 f2; set ::seg [list $u $f1 $f2] }
# inverse of the monotone loading branch from the virgin state (k3 > 0: strictly increasing)
proc virginDisp {P} {
  set uy1 [expr {$::fy1 / $::k1}]; set uy2 [expr {$::fy2 / $::k2}]
  set lo 0.0; set hi 1.0
  # bisection on a piecewise-linear function: 200 halvings reach round-off
  for {set i 0} {$i < 200} {incr i} {
    set mid [expr {0.5 * ($lo + $hi)}]
    if {[force $mid] < $P} { set lo $mid } else { set hi $mid }
  }
  return [expr {0.5 * ($lo + $hi)}]
}

model basic -ndm 1 -ndf 1
node 1 0.0
node 2 0.0
fix 1 1
uniaxialMaterial ElasticPP 1 $k1 [expr {$fy1 / $k1}]
uniaxialMaterial ElasticPP 2 $k2 [expr {$fy2 / $k2}]
uniaxialMaterial Elastic 3 $k3
element zeroLength 1 1 2 -mat 1 -dir 1
element zeroLength 2 1 2 -mat 2 -dir 1
element zeroLength 3 1 2 -mat 3 -dir 1
timeSeries Linear 1
pattern Plain 1 1 { load 2 1.0 }
constraints Plain; numberer Plain; system BandGeneral
test NormDispIncr 1e-12 50
algorithm Newton

# --- LoadControl 0 -> P1 = 14 (both springs yield) ---
set P1 14.0
set n 14
integrator LoadControl [expr {$P1 / $n}]
analysis Static
set worst 0.0
for {set i 1} {$i <= $n} {incr i} {
  if {[analyze 1] != 0} { error "LoadControl loading failed at step $i" }
  set worst [expr {max($worst, abs([nodeDisp 2 1] - [virginDisp [getTime %.17g]]))}]
}
checkAbs "LoadControl loading: u(lambda) on the closed-form virgin branch, max err" $worst 0.0 $TOL
check "LoadControl loading: u at P1 = (P1 - fy1 - fy2)/k3" [nodeDisp 2 1] [expr {($P1 - $fy1 - $fy2) / $k3}] $TOL
check "spring 1 force at P1 = fy1" [lindex [eleResponse 1 force] 1] $fy1 $TOL
newSegment [nodeDisp 2 1]

# --- LoadControl unloading P1 -> 0: elastic, k1 + k2 + k3 ---
# Newton on the current tangent (k3 only, both EPP springs at yield) overshoots into reverse
# yielding and cycles; the initial stiffness is the exact unloading stiffness here.
algorithm Newton -initial
integrator LoadControl [expr {-$P1 / $n}]
analysis Static
if {[analyze $n] != 0} { error "LoadControl unloading failed" }
checkAbs "LoadControl unloading: load factor back to 0" [getTime %.17g] 0.0 1e-12
set uRes [expr {($P1 - $fy1 - $fy2) / $k3 - $P1 / ($k1 + $k2 + $k3)}]
check "LoadControl unloading: residual u = u1 - P1/(k1+k2+k3)" [nodeDisp 2 1] $uRes $TOL
checkAbs "closed form is self-consistent: force(u_res) = 0" [force $uRes] 0.0 1e-12

# --- DisplacementControl to -0.4 (reverse yielding), then back to +0.1 ---
algorithm Newton
foreach {target steps} {-0.4 25 0.1 20} {
  newSegment [nodeDisp 2 1]
  set du [expr {($target - [nodeDisp 2 1]) / $steps}]
  integrator DisplacementControl 2 1 $du
  analysis Static
  set worst 0.0
  for {set i 1} {$i <= $steps} {incr i} {
    if {[analyze 1] != 0} { error "DisplacementControl to $target failed at step $i" }
    set worst [expr {max($worst, abs([getTime %.17g] - [force [nodeDisp 2 1]]))}]
  }
  check "DisplacementControl to $target: u reached" [nodeDisp 2 1] $target $TOL
  checkAbs "DisplacementControl to $target: lambda(u) vs closed form, max err" $worst 0.0 [expr {$TOL * 100.0}]
}
check "DisplacementControl at u=0.1: lambda = closed form" [getTime %.17g] [force 0.1] $TOL
wipe

# --- failure past the limit load: EPP spring alone, LoadControl ---
model basic -ndm 1 -ndf 1
node 1 0.0
node 2 0.0
fix 1 1
uniaxialMaterial ElasticPP 1 $k1 [expr {$fy1 / $k1}]
element zeroLength 1 1 2 -mat 1 -dir 1
timeSeries Linear 1
pattern Plain 1 1 { load 2 1.0 }
constraints Plain; numberer Plain; system BandGeneral
test NormDispIncr 1e-12 20
algorithm Newton
integrator LoadControl 2.0
analysis Static
checkTrue "EPP spring: 2 load steps below fy converge" [expr {[analyze 2] == 0}]
set uBefore [nodeDisp 2 1]
set tBefore [getTime %.17g]
set rc [catch {analyze 1} result]
checkTrue "EPP spring past fy: analyze gives no Tcl error" [expr {$rc == 0}]
checkTrue "EPP spring past fy: analyze returns a negative code (got $result)" [expr {$rc == 0 && $result < 0}]
check "EPP spring past fy: time stays at the last converged step" [getTime %.17g] $tBefore 1e-12
check "EPP spring past fy: displacement stays at the last converged step" [nodeDisp 2 1] $uBefore 1e-12
check "EPP spring: last converged u = 4/k1" $uBefore [expr {4.0 / $k1}] $TOL
wipe
finish
