# SPDX-License-Identifier: MIT
# Elastic fiber-section cantilevers. Source: elementary beam theory (Gere & Timoshenko, Mechanics
# of Materials, App. G, cantilever case 1; bars in tension and torsion): tip deflection
# P L^3 / (3 E I), elongation N L / (E A), twist T L / (G J).
#
# The section is a rectangle of Elastic fibers (patch rect, n equal layers). Its second moment is
# that of the fiber layout, sum(A_i y_i^2), computed here from the layer midpoints:
# b h^3/12 (1 - 1/n^2), so the closed forms use the discrete I (the comparison is exact then).
#
# Part A (3D, section centred on the axis): one forceBeamColumn (Lobatto, 5 points) and one
# dispBeamColumn both reproduce the closed forms to round-off, because the exact curvature is
# linear and the element fields contain it.
# Part B (2D, reference axis on the bottom face, so axial force and curvature couple through
# S = sum(A_i y_i)): with no axial force the exact section deformations are kz = M / EIc and
# eps0 = (S/A) kz, EIc = E (I - S^2/A) (centroidal), so the tip deflection is P L^3 / (3 EIc) and
# the tip axial displacement (S/A) P L^2 / (2 EIc). The force-based element is exact with one
# element; the displacement-based element (constant axial strain) cannot represent the linear
# eps0, which stiffens its bending, and its tip deflection converges as elements are added: the
# errors shrink and the observed order is reported (second order).
source [file join [file dirname [info script]] .. lib check.tcl]

set kExactTol 1e-9    ;# round-off: exact solutions
set E 3.0e7; set b 0.4; set h 0.6; set L 5.0; set G 1.2e7; set J 0.01
set nY 20; set nZ 10

proc layerSums {n lo hi} {
  # sum of dy, y dy, y^2 dy over n equal layers between lo and hi (midpoint rule, as the fibers)
  set d [expr {($hi - $lo) / double($n)}]
  set s0 0.0; set s1 0.0; set s2 0.0
  for {set i 0} {$i < $n} {incr i} {
    set y [expr {$lo + ($i + 0.5) * $d}]
    set s0 [expr {$s0 + $d}]; set s1 [expr {$s1 + $y * $d}]; set s2 [expr {$s2 + $y * $y * $d}]
  }
  return [list $s0 $s1 $s2]
}

# ------------------------------------------------------------------ Part A: 3D, centred section
lassign [layerSums $nY [expr {-$h / 2}] [expr {$h / 2}]] sy0 sy1 sy2
lassign [layerSums $nZ [expr {-$b / 2}] [expr {$b / 2}]] sz0 sz1 sz2
set A [expr {$b * $h}]
set Iz [expr {$sy2 * $b}]
set Iy [expr {$sz2 * $h}]
set Py 100.0; set Pz -70.0; set N 500.0; set T 40.0

foreach type {forceBeamColumn dispBeamColumn} {
  wipe
  model basic -ndm 3 -ndf 6
  uniaxialMaterial Elastic 1 $E
  section Fiber 1 -GJ [expr {$G * $J}] {
    patch rect 1 $nY $nZ [expr {-$h / 2}] [expr {-$b / 2}] [expr {$h / 2}] [expr {$b / 2}]
  }
  beamIntegration Lobatto 1 1 5
  geomTransf Linear 1 0.0 0.0 1.0
  node 1 0 0 0; node 2 $L 0 0
  fix 1 1 1 1 1 1 1
  element $type 1 1 2 1 1
  timeSeries Linear 1
  pattern Plain 1 1 { load 2 $N $Py $Pz $T 0 0 }
  constraints Plain; numberer Plain; system BandGeneral
  test NormDispIncr 1e-12 10; algorithm Newton
  integrator LoadControl 1.0; analysis Static
  checkTrue "$type 3D: analyze returns 0" [expr {[analyze 1] == 0}]
  check "$type 3D one element: tip uy = Py L^3/(3 E Iz)" [nodeDisp 2 2] [expr {$Py * $L ** 3 / (3 * $E * $Iz)}] $kExactTol
  check "$type 3D one element: tip uz = Pz L^3/(3 E Iy)" [nodeDisp 2 3] [expr {$Pz * $L ** 3 / (3 * $E * $Iy)}] $kExactTol
  check "$type 3D one element: tip ux = N L/(E A)" [nodeDisp 2 1] [expr {$N * $L / ($E * $A)}] $kExactTol
  check "$type 3D one element: tip twist = T L/(G J)" [nodeDisp 2 4] [expr {$T * $L / ($G * $J)}] $kExactTol
  check "$type 3D one element: tip rz = Py L^2/(2 E Iz)" [nodeDisp 2 6] [expr {$Py * $L ** 2 / (2 * $E * $Iz)}] $kExactTol
}

# ------------------------------------------------------------------ Part B: 2D, offset section
lassign [layerSums $nY 0.0 $h] s0 s1 s2
set A [expr {$b * $s0}]; set S [expr {$b * $s1}]; set I [expr {$b * $s2}]
set EIc [expr {$E * ($I - $S * $S / $A)}]
set P 50.0
set vExact [expr {$P * $L ** 3 / (3.0 * $EIc)}]
set uExact [expr {$S / $A * $P * $L ** 2 / (2.0 * $EIc)}]
puts [format "offset section: EIc = %.6g (centroidal, = E b h^3/12 (1 - 1/n^2) = %.6g)" $EIc \
    [expr {$E * $b * $h ** 3 / 12.0 * (1.0 - 1.0 / ($nY * $nY))}]]

# The section's fibers lie from y = 0 to h. With -noCentroid its reference axis is y = 0, the
# element's axis: bending couples with the axial strain there. Without it (OpenSees' default) the
# axis is the fibers' area centroid, y = h/2: no coupling, the same deflection.
proc offsetCantilever {type nEle {axis -noCentroid}} {
  global E b h L P nY
  wipe
  model basic -ndm 2 -ndf 3
  uniaxialMaterial Elastic 1 $E
  section Fiber 1 {*}$axis { patch rect 1 $nY 1 0.0 [expr {-$b / 2}] $h [expr {$b / 2}] }
  beamIntegration Legendre 1 1 3
  geomTransf Linear 1
  for {set i 0} {$i <= $nEle} {incr i} { node [expr {$i + 1}] [expr {$L * $i / double($nEle)}] 0.0 }
  fix 1 1 1 1
  for {set i 1} {$i <= $nEle} {incr i} { element $type $i $i [expr {$i + 1}] 1 1 }
  timeSeries Linear 1
  pattern Plain 1 1 { load [expr {$nEle + 1}] 0.0 $P 0.0 }
  constraints Plain; numberer Plain; system BandGeneral
  test NormDispIncr 1e-12 10; algorithm Newton
  integrator LoadControl 1.0; analysis Static
  if {[analyze 1] != 0} { return {nan nan} }
  return [list [nodeDisp [expr {$nEle + 1}] 2] [nodeDisp [expr {$nEle + 1}] 1]]
}

lassign [offsetCantilever forceBeamColumn 1] v u
check "forceBeamColumn, 1 element, offset axis: tip deflection P L^3/(3 EIc)" $v $vExact $kExactTol
check "forceBeamColumn, 1 element, offset axis: tip axial (S/A) P L^2/(2 EIc)" $u $uExact $kExactTol
lassign [offsetCantilever forceBeamColumn 1 {}] v u
check "forceBeamColumn, axis at the centroid (default): tip deflection P L^3/(3 EIc)" $v $vExact \
    $kExactTol
checkAbs "forceBeamColumn, axis at the centroid (default): no tip axial displacement" $u 0.0 \
    [expr {1e-12 * abs($uExact)}]

set prevV {}; set prevU {}
set errs {}
foreach n {1 2 4 8 16} {
  lassign [offsetCantilever dispBeamColumn $n] v u
  set ev [expr {abs($v - $vExact) / $vExact}]
  set eu [expr {abs($u - $uExact) / abs($uExact)}]
  puts [format "dispBeamColumn %2d elements: tip deflection rel. error %.3e, tip axial rel. error %.3e" $n $ev $eu]
  if {$prevV ne ""} {
    set ov [expr {log($prevV / $ev) / log(2.0)}]
    set ou [expr {log($prevU / $eu) / log(2.0)}]
    puts [format "   observed order from %d to %d elements: deflection %.2f, axial %.2f" [expr {$n / 2}] $n $ov $ou]
    checkTrue "dispBeamColumn: deflection error shrinks from [expr {$n / 2}] to $n elements" [expr {$ev < $prevV}]
  }
  # The weak axial equilibrium (N = 0 on average per element) makes each element's constant
  # axial strain the mean of the exact linear eps0, so the tip axial displacement is exact.
  check "dispBeamColumn $n elements: tip axial (S/A) P L^2/(2 EIc) (element-mean strain is exact)" $u $uExact $kExactTol
  set prevV $ev; set prevU $eu
  lappend errs $ev
}
# Halving the element size should at least quarter the deflection error (second order).
set order [expr {log([lindex $errs 3] / [lindex $errs 4]) / log(2.0)}]
checkTrue [format "dispBeamColumn: observed order of the deflection error >= 1.9 (got %.2f)" $order] [expr {$order >= 1.9}]
finish
