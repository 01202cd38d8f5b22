# SPDX-License-Identifier: MIT
# Member loads on elastic, force- and displacement-based beams: runs the input
# verification/opensees/eleload-beam.tcl, compares every number with OpenSees 3.8.0's CSV for it and
# checks the Euler-Bernoulli closed forms (Gere & Timoshenko, Mechanics of Materials, beam
# deflection tables).
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] .. lib opensees-csv.tcl]

source [openseesReference eleload-beam.tcl]
set r [compareOpenSeesCsv eleload-beam.csv [openseesReference eleload-beam.csv] 1e-7 1e-10]
proc value {key} { global r; return [dict get $r $key] }

set L 6.0; set E 200.0e6; set A 0.01; set Iz 1.0e-4; set Iy 2.0e-4
set EI [expr {$E*$Iz}]; set EA [expr {$E*$A}]
foreach type {elastic force disp} {
  # Simply supported, w = -10 kN/m, axial 2 kN/m.
  check "$type: simply supported midspan deflection 5wL^4/384EI" [value ss-uniform-$type,uy-mid] [expr {-5*10.0*$L**4/(384*$EI)}] 1e-9
  check "$type: simply supported end rotation wL^3/24EI" [value ss-uniform-$type,rz-end] [expr {-10.0*$L**3/(24*$EI)}] 1e-9
  check "$type: axial end displacement wx L^2/2EA" [value ss-uniform-$type,ux-end] [expr {2.0*$L**2/(2*$EA)}] 1e-9
  check "$type: end shear wL/2 in the local forces" [value ss-uniform-$type,localForce1] [expr {10.0*$L/2}] 1e-9
  check "$type: midspan moment wL^2/8 at the end of element 1" [value ss-uniform-$type,localForce5] [expr {10.0*$L**2/8}] 1e-9
  # Cantilever, P = -20 kN at a = 0.3 L, axial 5 kN. A force-based element integrates the kinked
  # section forces of a point load with its quadrature (5 Lobatto points), so it is only as exact
  # as that rule: it is checked against OpenSees' numbers above, not against the closed form.
  if {$type eq "force"} continue
  set a [expr {0.3*$L}]
  check "$type: cantilever tip deflection Pa^2(3L-a)/6EI" [value cant-point-$type,uy-tip] [expr {-20.0*$a**2*(3*$L-$a)/(6*$EI)}] 1e-9
  check "$type: cantilever tip rotation Pa^2/2EI" [value cant-point-$type,rz-tip] [expr {-20.0*$a**2/(2*$EI)}] 1e-9
  check "$type: cantilever axial tip displacement Na/EA" [value cant-point-$type,ux-tip] [expr {5.0*$a/$EA}] 1e-9
  check "$type: fixed-end moment Pa at the support" [value cant-point-$type,localForce2] [expr {20.0*$a}] 1e-9
}
# Cantilever, w = -8 kN/m on [L/4, 3L/4]: integrals of the point-load influence lines.
set a [expr {0.25*$L}]; set b [expr {0.75*$L}]
foreach type {elastic} {
  check "$type: partial uniform load, tip deflection" [value cant-partial-$type,uy-tip] \
      [expr {-8.0/(6*$EI)*(($L*$b**3 - $b**4/4) - ($L*$a**3 - $a**4/4))}] 1e-9
  check "$type: partial uniform load, tip rotation" [value cant-partial-$type,rz-tip] \
      [expr {-8.0*($b**3 - $a**3)/(6*$EI)}] 1e-9
}
# Cantilever, load varying linearly from (wy, wx) = (-4, 1) at 0.2 L to (-10, 3) at 0.9 L:
# integrals of the point-load influence lines by Simpson's rule (independent of the element).
proc simpson {f a b n} {
  set h [expr {($b - $a)/$n}]
  set sum [expr {[apply $f $a] + [apply $f $b]}]
  for {set k 1} {$k < $n} {incr k} { set sum [expr {$sum + ($k % 2 ? 4 : 2)*[apply $f [expr {$a + $k*$h}]]}] }
  return [expr {$sum*$h/3}]
}
set a [expr {0.2*$L}]; set b [expr {0.9*$L}]
set wy [list s "expr {-4.0 + (-10.0 + 4.0)*(\$s - $a)/($b - $a)}"]
set wx [list s "expr {1.0 + (3.0 - 1.0)*(\$s - $a)/($b - $a)}"]
set deflection [simpson [list s "expr {\[apply {$wy} \$s\]*\$s**2*(3*$L - \$s)/(6*$EI)}"] $a $b 2000]
set rotation [simpson [list s "expr {\[apply {$wy} \$s\]*\$s**2/(2*$EI)}"] $a $b 2000]
set axial [simpson [list s "expr {\[apply {$wx} \$s\]*\$s/$EA}"] $a $b 2000]
check "elastic: linearly varying load, tip deflection" [value cant-trapezoid-elastic,uy-tip] $deflection 1e-9
check "elastic: linearly varying load, tip rotation" [value cant-trapezoid-elastic,rz-tip] $rotation 1e-9
check "elastic: linearly varying axial load, tip displacement" [value cant-trapezoid-elastic,ux-tip] $axial 1e-9
set full [expr {-10.0*$L**4/(8*$EI)}]
check "Linear series: half the load at t = 0.5" [value series-elastic,uy-tip-half] [expr {$full/2}] 1e-9
check "Linear series: full load wL^4/8EI at t = 1" [value series-elastic,uy-tip-full] $full 1e-9
checkAbs "removing the pattern removes its member loads" [value series-elastic,uy-tip-removed] 0.0 1e-12
# 3D cantilever: uniform (wy, wz, wx) = (-4, 3, 1.5) and point (Py, Pz, Px) = (6, -7, -2) at 0.6 L.
set a [expr {0.6*$L}]
set EIy [expr {$E*$Iy}]
foreach type {elastic disp} {
  check "$type 3D: axial tip displacement" [value cant3d-$type,u1] [expr {(1.5*$L**2/2 - 2.0*$a)/$EA}] 1e-9
  check "$type 3D: tip deflection along y" [value cant3d-$type,u2] [expr {(-4.0*$L**4/8 + 6.0*$a**2*(3*$L-$a)/6)/$EI}] 1e-9
  check "$type 3D: tip deflection along z" [value cant3d-$type,u3] [expr {(3.0*$L**4/8 - 7.0*$a**2*(3*$L-$a)/6)/$EIy}] 1e-9
  check "$type 3D: tip rotation about y (-dw/dx)" [value cant3d-$type,u5] [expr {-(3.0*$L**3/6 - 7.0*$a**2/2)/$EIy}] 1e-9
  check "$type 3D: tip rotation about z" [value cant3d-$type,u6] [expr {(-4.0*$L**3/6 + 6.0*$a**2/2)/$EI}] 1e-9
}
finish
