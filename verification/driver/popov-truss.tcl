# SPDX-License-Identifier: MIT
# Popov's symmetric three-bar truss: elastic forces, first yield, limit load, unloading.
#
# Source: E. P. Popov, Engineering Mechanics of Solids (2nd ed.), statically indeterminate
# elastic-plastic three-bar truss (Ch. 2, limit analysis): three bars of equal A and E meet at a
# joint; the middle bar is vertical with length L, the outer bars make angle alpha with it
# (length L / cos alpha); a vertical load P acts at the joint. Closed forms (c = cos alpha):
#   elastic: N_mid = P / (1 + 2c^3), N_out = P c^2 / (1 + 2c^3), delta = P L / (E A (1 + 2c^3));
#   first yield (middle bar): P_y = sy A (1 + 2c^3) at delta_y = sy L / E;
#   contained plastic range: P = sy A + 2 E A c^3 delta / L;
#   limit load P_L = sy A (1 + 2c) reached at delta_L = sy L / (E c^2);
#   elastic unloading with the initial stiffness K = E A (1 + 2c^3) / L; after unloading from the
#   limit state by Delta = P_L / K: N_mid = sy A - E A Delta / L, N_out = sy A - E A c^2 Delta / L
#   (self-equilibrated residual forces: N_mid + 2 c N_out = 0).
# The joint's horizontal dof is fixed: it is zero by symmetry, and once all three bars have
# yielded it has no stiffness.
source [file join [file dirname [info script]] .. lib check.tcl]

set TOL 1e-8

set E 29000.0     ;# ksi
set A 1.5         ;# in^2
set sy 36.0       ;# ksi
set L 120.0       ;# in
set alpha [expr {acos(-1.0) / 4.0}]
set c [expr {cos($alpha)}]
set K [expr {$E * $A * (1.0 + 2.0 * $c ** 3) / $L}]
set Py [expr {$sy * $A * (1.0 + 2.0 * $c ** 3)}]
set dy [expr {$sy * $L / $E}]
set PL [expr {$sy * $A * (1.0 + 2.0 * $c)}]
set dL [expr {$sy * $L / ($E * $c * $c)}]

model basic -ndm 2 -ndf 2
set s [expr {$L * tan($alpha)}]
node 1 [expr {-$s}] $L
node 2 0.0 $L
node 3 $s $L
node 4 0.0 0.0
fix 1 1 1
fix 2 1 1
fix 3 1 1
fix 4 1 0
uniaxialMaterial ElasticPP 1 $E [expr {$sy / $E}]
element truss 1 1 4 $A 1
element truss 2 2 4 $A 1
element truss 3 3 4 $A 1

timeSeries Linear 1
pattern Plain 1 1 { load 4 0.0 -1.0 }

proc axial {e} { return [lindex [eleResponse $e axialForce] 0] }
proc defl {} { return [expr {-[nodeDisp 4 2]}] }

# --- elastic range: LoadControl to 0.8 P_y ---
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1e-12 20
algorithm Newton
set P1 [expr {0.8 * $Py}]
integrator LoadControl [expr {$P1 / 4.0}]
analysis Static
checkTrue "LoadControl elastic steps converge" [expr {[analyze 4] == 0}]
check "Popov 3-bar elastic: load factor" [getTime %.17g] $P1 $TOL
check "Popov 3-bar elastic: delta = P L/(E A (1+2c^3))" [defl] [expr {$P1 / $K}] $TOL
check "Popov 3-bar elastic: N_mid = P/(1+2c^3)" [axial 2] [expr {$P1 / (1.0 + 2.0 * $c ** 3)}] $TOL
check "Popov 3-bar elastic: N_out = P c^2/(1+2c^3) (bar 1)" [axial 1] [expr {$P1 * $c * $c / (1.0 + 2.0 * $c ** 3)}] $TOL
check "Popov 3-bar elastic: N_out = P c^2/(1+2c^3) (bar 3)" [axial 3] [expr {$P1 * $c * $c / (1.0 + 2.0 * $c ** 3)}] $TOL
reactions
set ry [expr {[nodeReaction 1 2] + [nodeReaction 2 2] + [nodeReaction 3 2]}]
check "Popov 3-bar elastic: vertical reactions sum to P" $ry $P1 $TOL

# --- contained plastic range: DisplacementControl to halfway between delta_y and delta_L ---
set dMid [expr {0.5 * ($dy + $dL)}]
set n 10
integrator DisplacementControl 4 2 [expr {-($dMid - [defl]) / $n}]
analysis Static
checkTrue "DisplacementControl through first yield converges" [expr {[analyze $n] == 0}]
check "Popov 3-bar contained plastic: delta" [defl] $dMid $TOL
check "Popov 3-bar contained plastic: P = sy A + 2 E A c^3 delta/L" [getTime %.17g] \
  [expr {$sy * $A + 2.0 * $E * $A * $c ** 3 * $dMid / $L}] $TOL
check "Popov 3-bar contained plastic: N_mid = sy A" [axial 2] [expr {$sy * $A}] $TOL
check "Popov 3-bar contained plastic: N_out = E A c^2 delta/L" [axial 1] [expr {$E * $A * $c * $c * $dMid / $L}] $TOL
checkTrue "Popov 3-bar: first yield load P_y lies below the current load" [expr {$Py < [getTime %.17g]}]

# --- limit load: push on to delta_1 = (1 - 1e-6) delta_L, just short of the state where the outer
#     bars yield and the truss becomes a mechanism (there every bar has zero tangent; like
#     OpenSees, Newton and DisplacementControl's predictor need a non-singular tangent, so the
#     plateau itself is not traversed) ---
set d1 [expr {(1.0 - 1.0e-6) * $dL}]
integrator DisplacementControl 4 2 [expr {-($d1 - [defl]) / $n}]
analysis Static
checkTrue "DisplacementControl to delta_1 converges" [expr {[analyze $n] == 0}]
check "Popov 3-bar: delta_1 reached" [defl] $d1 $TOL
set P1 [expr {$sy * $A + 2.0 * $E * $A * $c ** 3 * $d1 / $L}]
check "Popov 3-bar at delta_1: P = sy A + 2 E A c^3 delta/L" [getTime %.17g] $P1 $TOL
check "Popov 3-bar limit load P_L = sy A (1 + 2 cos alpha) approached at delta_L" [getTime %.17g] $PL 1e-5
check "Popov 3-bar at limit: N_mid = sy A" [axial 2] [expr {$sy * $A}] $TOL
check "Popov 3-bar at limit: N_out -> sy A" [axial 3] [expr {$sy * $A}] 1e-5

# --- elastic unloading to P = 0 (LoadControl) ---
set Delta [expr {$P1 / $K}]
integrator LoadControl [expr {-$P1 / $n}]
analysis Static
checkTrue "LoadControl unloading converges" [expr {[analyze $n] == 0}]
checkAbs "Popov 3-bar unloaded: load factor 0 (in units of P_L)" [expr {[getTime %.17g] / $PL}] 0.0 $TOL
check "Popov 3-bar residual deflection delta_1 - P_1/K" [defl] [expr {$d1 - $Delta}] $TOL
check "Popov 3-bar residual N_mid = sy A - E A Delta/L" [axial 2] [expr {$sy * $A - $E * $A * $Delta / $L}] $TOL
check "Popov 3-bar residual N_out = E A c^2 (delta_1 - Delta)/L" [axial 1] [expr {$E * $A * $c * $c * ($d1 - $Delta) / $L}] $TOL
check "Popov 3-bar residual N_out -> sy A - E A c^2 (P_L/K)/L (Popov)" [axial 1] [expr {$sy * $A - $E * $A * $c * $c * $PL / $K / $L}] 1e-4
checkAbs "Popov 3-bar residual forces self-equilibrated N_mid + 2c N_out (in sy A)" \
  [expr {([axial 2] + 2.0 * $c * [axial 1]) / ($sy * $A)}] 0.0 $TOL
wipe
finish
