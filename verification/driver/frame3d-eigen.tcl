# SPDX-License-Identifier: MIT
# Eigenvalues of a two-storey 3D frame (2 x 1 bays) with rigid floor diaphragms.
#
# Source (closed form, independent of the program): a shear building. Each floor is a rigid
# diaphragm (rigidLink beam from a master node at the floor's centre of mass to every column top)
# whose master has uz, rx, ry fixed, so every column is fixed-fixed against rotation about its
# bending axes: lateral stiffness 12 E I / h^3 per column (Chopra, Dynamics of Structures, 4th ed.,
# §1.3 and §9.2 shear building), torsional storey stiffness
#   k_theta = sum(k_x,i (y_i - yc)^2 + k_y,i (x_i - xc)^2) + sum G J / h
# (Chopra §9.5, one-storey/multistorey unsymmetric-plan systems, here symmetric: uncoupled).
# Per direction (x, y, theta) the two floors give K = [[k1+k2, -k2], [-k2, k2]], M = diag(m1, m2):
#   m1 m2 lambda^2 - (m1 k2 + m2 (k1 + k2)) lambda + k1 k2 = 0,
# and the mode shape phi2/phi1 = (k1 + k2 - lambda m1) / k2. Columns are split in two elements with
# a massless mid-height node (elastic elements are exact, so this changes nothing but the size:
# 78 free dofs, 6 with mass). The same frame is solved with Transformation constraints, with
# Penalty constraints, and with eigen -fullGenLapack; all are compared with the closed form.
source [file join [file dirname [info script]] .. lib check.tcl]

set TOL_TRANSFORMATION 1e-8
set TOL_PENALTY 1e-5         ;# rigid links and fixes enforced by alpha = 1e12 against k ~ 1e4..1e6
set TOL_SHAPE 1e-6

# units kN, m, t
set E 2.5e7; set G [expr {2.5e7 / 2.4}]
set A 0.2; set Iy 2.6667e-3; set Iz 4.1667e-3; set J 5.0e-3
set xs {0.0 6.0 12.0}; set ys {0.0 5.0}
set xc 6.0; set yc 2.5
set hs {4.0 3.5}
set zs {0.0 4.0 7.5}
set masses {60.0 45.0}
set inertias [lmap mm $masses {expr {$mm * (12.0 ** 2 + 5.0 ** 2) / 12.0}}]

# column orientation: vertical axis x_local = +Z, vecxz = +X => local z = +X, local y = -Y;
# a displacement along X bends about local y (Iy), along Y about local z (Iz).
set kx {}; set ky {}; set kt {}
foreach h $hs {
  set kxc [expr {12.0 * $E * $Iy / $h ** 3}]
  set kyc [expr {12.0 * $E * $Iz / $h ** 3}]
  set sx 0.0; set sy 0.0; set st 0.0
  foreach x $xs { foreach y $ys {
    set sx [expr {$sx + $kxc}]
    set sy [expr {$sy + $kyc}]
    set st [expr {$st + $kxc * ($y - $yc) ** 2 + $kyc * ($x - $xc) ** 2 + $G * $J / $h}]
  } }
  lappend kx $sx; lappend ky $sy; lappend kt $st
}

# closed-form eigenpairs of a 2-dof shear building: list of {lambda ratio}
proc twoStorey {k1 k2 m1 m2} {
  set B [expr {$m1 * $k2 + $m2 * ($k1 + $k2)}]
  set D [expr {sqrt($B * $B - 4.0 * $m1 * $m2 * $k1 * $k2)}]
  set out {}
  foreach l [list [expr {($B - $D) / (2.0 * $m1 * $m2)}] [expr {($B + $D) / (2.0 * $m1 * $m2)}]] {
    lappend out [list $l [expr {($k1 + $k2 - $l * $m1) / $k2}]]
  }
  return $out
}
set expected {}
lassign $masses m1 m2
lassign $inertias J1 J2
foreach pair [twoStorey {*}$kx $m1 $m2] { lappend expected [list {*}$pair 1] }   ;# dof 1 = ux
foreach pair [twoStorey {*}$ky $m1 $m2] { lappend expected [list {*}$pair 2] }   ;# dof 2 = uy
foreach pair [twoStorey {*}$kt $J1 $J2] { lappend expected [list {*}$pair 6] }   ;# dof 6 = rz
set expected [lsort -real -index 0 $expected]

proc buildFrame {handler} {
  wipe
  model basic -ndm 3 -ndf 6
  geomTransf Linear 1 1.0 0.0 0.0
  set tag 0
  set eleTag 0
  # base, mid-height and top nodes of every column line; floor masters 1001, 1002
  foreach x $::xs { foreach y $::ys {
    incr tag
    set line($tag) [list $x $y]
    node [expr {$tag}] $x $y 0.0
    fix $tag 1 1 1 1 1 1
  } }
  set nLines $tag
  for {set f 1} {$f <= 2} {incr f} {
    set z0 [lindex $::zs [expr {$f - 1}]]
    set z1 [lindex $::zs $f]
    set master [expr {1000 + $f}]
    node $master $::xc $::yc $z1 -mass [lindex $::masses [expr {$f - 1}]] [lindex $::masses [expr {$f - 1}]] 0.0 0.0 0.0 [lindex $::inertias [expr {$f - 1}]]
    fix $master 0 0 1 1 1 0
    for {set c 1} {$c <= $nLines} {incr c} {
      lassign $line($c) x y
      set bottom [expr {($f - 1) * 100 + $c}]
      set mid [expr {$f * 100 + 50 + $c}]
      set top [expr {$f * 100 + $c}]
      node $mid $x $y [expr {0.5 * ($z0 + $z1)}]
      node $top $x $y $z1
      element elasticBeamColumn [incr eleTag] $bottom $mid $::A $::E $::G $::J $::Iy $::Iz 1
      element elasticBeamColumn [incr eleTag] $mid $top $::A $::E $::G $::J $::Iy $::Iz 1
      rigidLink beam $master $top
    }
  }
  if {$handler eq "Penalty"} { constraints Penalty 1.0e12 1.0e12 } else { constraints $handler }
  numberer RCM
  system UmfPack
}

proc compare {label handler eigenArgs tol} {
  buildFrame $handler
  set lambdas [eigen {*}$eigenArgs 6]
  checkTrue "$label: eigen returned 6 values" [expr {[llength $lambdas] == 6}]
  set i 0
  foreach e $::expected l $lambdas {
    incr i
    lassign $e le ratio dof
    check "$label: mode $i lambda vs shear-building closed form (dof $dof)" $l $le $tol
    if {$eigenArgs eq ""} {
      set p1 [nodeEigenvector 1001 $i $dof]
      set p2 [nodeEigenvector 1002 $i $dof]
      check "$label: mode $i shape phi2/phi1 = (k1+k2-lambda m1)/k2" [expr {$p2 / $p1}] $ratio [expr {max($::TOL_SHAPE, $tol)}]
    }
  }
}

compare "3D frame, Transformation" Transformation {} $TOL_TRANSFORMATION
compare "3D frame, Penalty" Penalty {} $TOL_PENALTY
compare "3D frame, Transformation, -fullGenLapack" Transformation {-fullGenLapack} $TOL_TRANSFORMATION
wipe
finish
