# SPDX-License-Identifier: MIT
# 3D corotational transformation: an elastic cantilever (along X) rolled up by a tip moment about
# Z, and the same about an oblique bending axis.
# Source: pure bending of an inextensible elastica (Bisshopp & Drucker 1945, Q. Appl. Math. 3;
# the standard corotational benchmark of Crisfield 1990 / Battini & Pacoste 2002): the curvature
# is M/EI everywhere, so the tip rotation is M L/EI exactly. With n straight corotational
# elements, each element bends symmetrically (end rotations +-phi/2 about its chord,
# phi = M L0/EI) and keeps its length (N = 0), so the nodes lie on a polygon of chords of length
# L0 with directions (k - 1/2) phi, k = 1..n: tip x = sum L0 cos((k-1/2)phi), tip y = sum L0
# sin((k-1/2)phi). That polygon tends to the circle R (sin t, 1 - cos t), R = L/t, as n grows.
source [file join [file dirname [info script]] .. lib check.tcl]

set kTol 1e-7  ;# Newton tolerance 1e-12 on displacements of order 1: exact up to convergence
set L 10.0; set E 2.0e8; set A 0.01; set Iz 2.0e-5; set Iy 3.0e-5; set G 8.0e7; set J 1.0e-5
set n 12
set PI [expr {acos(-1.0)}]

foreach {label theta} [list "quarter turn" [expr {$PI / 2.0}] "full circle" [expr {2.0 * $PI}]] {
  wipe
  model basic -ndm 3 -ndf 6
  for {set i 0} {$i <= $n} {incr i} { node [expr {$i + 1}] [expr {$L * $i / $n}] 0.0 0.0 }
  fix 1 1 1 1 1 1 1
  geomTransf Corotational 1 0.0 0.0 1.0
  for {set i 1} {$i <= $n} {incr i} {
    element elasticBeamColumn $i $i [expr {$i + 1}] $A $E $G $J $Iy $Iz 1
  }
  set M [expr {$theta * $E * $Iz / $L}]
  timeSeries Linear 1
  pattern Plain 1 1 { load [expr {$n + 1}] 0 0 0 0 0 $M }
  constraints Plain; numberer Plain; system BandGeneral
  test NormDispIncr 1e-12 50; algorithm Newton
  set steps 40
  integrator LoadControl [expr {1.0 / $steps}]; analysis Static
  checkTrue "$label: $steps load steps converge" [expr {[analyze $steps] == 0}]
  set phi [expr {$theta / $n}]
  set l0 [expr {$L / $n}]
  set x 0.0; set y 0.0
  for {set k 1} {$k <= $n} {incr k} {
    set x [expr {$x + $l0 * cos(($k - 0.5) * $phi)}]
    set y [expr {$y + $l0 * sin(($k - 0.5) * $phi)}]
  }
  set tip [expr {$n + 1}]
  checkAbs "$label: tip x = polygon of chords" [expr {$L + [nodeDisp $tip 1]}] $x [expr {$kTol * $L}]
  checkAbs "$label: tip y = polygon of chords" [nodeDisp $tip 2] $y [expr {$kTol * $L}]
  checkAbs "$label: out-of-plane tip z stays 0" [nodeDisp $tip 3] 0.0 [expr {$kTol * $L}]
  # For the rotation dofs the increments are spins about fixed global axes; about Z alone they add.
  checkAbs "$label: tip rotation = M L/EI" [nodeDisp $tip 6] $theta $kTol
  set R [expr {$L / $theta}]
  puts [format "%s: tip (%.6f, %.6f); circle (%.6f, %.6f); polygon-to-circle difference %.2e" \
      $label [expr {$L + [nodeDisp $tip 1]}] [nodeDisp $tip 2] [expr {$R * sin($theta)}] \
      [expr {$R * (1 - cos($theta))}] [expr {hypot($x - $R * sin($theta), $y - $R * (1 - cos($theta)))}]]
}
finish
