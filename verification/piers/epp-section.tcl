# SPDX-License-Identifier: MIT
# Moment-curvature of a rectangular section of elastic-perfectly-plastic fibers, through a
# zeroLengthSection (its rotation is the curvature).
# Source: plastic bending of a rectangle (Gere & Timoshenko, Mechanics of Materials, sec. 6.10;
# Neal, The Plastic Methods of Structural Analysis, ch. 1-2):
#  - pure bending, phi >= phi_y: M = Mp [1 - (1/3)(phi_y/phi)^2], Mp = fy b h^2/4,
#    phi_y = 2 fy/(E h);
#  - with an axial force P (|P| <= Py = fy b h), at full plasticity: M/Mp = 1 - (P/Py)^2.
# Fibers are n equal layers (midpoint rule); the error of the discrete section shrinks as n grows.
# The observed convergence order is the least-squares slope of log(error) against log(n).
source [file join [file dirname [info script]] .. lib check.tcl]

set E 2.0e8; set fy 4.0e5; set b 0.3; set h 0.5
set epsY [expr {$fy / $E}]
set phiY [expr {2.0 * $epsY / $h}]
set Mp [expr {$fy * $b * $h * $h / 4.0}]
set Py [expr {$fy * $b * $h}]

# Builds the model: node 1 fixed, node 2 free in axial and rotation; section of n layers.
proc buildSection {n} {
  global E fy b h
  wipe
  model basic -ndm 2 -ndf 3
  uniaxialMaterial ElasticPP 1 $E [expr {$fy / $E}]
  section Fiber 1 { patch rect 1 $n 1 [expr {-$h / 2}] [expr {-$b / 2}] [expr {$h / 2}] [expr {$b / 2}] }
  node 1 0.0 0.0; node 2 0.0 0.0
  fix 1 1 1 1; fix 2 0 1 0
  element zeroLengthSection 1 1 2 1
  constraints Plain; numberer Plain; system BandGeneral
  test NormDispIncr 1e-12 30; algorithm Newton
}

# Pushes the curvature to each value of `targets` (increasing) in steps of dphi; returns the
# moments reached there (nan when a step fails).
proc pushCurvature {targets dphi} {
  timeSeries Linear 2
  pattern Plain 2 2 { load 2 0.0 0.0 1.0 }
  integrator DisplacementControl 2 3 $dphi
  analysis Static
  set out {}
  foreach t $targets {
    while {[nodeDisp 2 3] < $t - 1e-12} {
      set step [expr {min($dphi, $t - [nodeDisp 2 3])}]
      integrator DisplacementControl 2 3 $step
      if {[analyze 1] != 0} { return [lrepeat [llength $targets] nan] }
    }
    lappend out [lindex [eleResponse 1 force] 5]
  }
  return $out
}

# ------------------------------------------------------------------ pure bending, convergence
# Up to 5 phi_y: with 10 layers the two central fibers stay elastic (strain eps_y/2), so the
# section tangent is not singular.
set ratios {1.5 2.0 3.0 4.0 5.0}
set targets {}
foreach r $ratios { lappend targets [expr {$r * $phiY}] }
set ns {10 20 40 80 160}
set errs {}
foreach n $ns {
  buildSection $n
  set ms [pushCurvature $targets [expr {$phiY / 10.0}]]
  set worst 0.0
  foreach r $ratios m $ms {
    set exact [expr {$Mp * (1.0 - 1.0 / (3.0 * $r * $r))}]
    set worst [expr {max($worst, abs($m - $exact) / $exact)}]
  }
  puts [format "n = %3d layers: largest relative moment error over phi/phi_y = {%s}: %.3e" $n $ratios $worst]
  lappend errs $worst
}
# Least-squares slope of log(err) on log(n).
set sx 0.0; set sy 0.0; set sxx 0.0; set sxy 0.0; set k [llength $ns]
foreach n $ns e $errs {
  set x [expr {log($n)}]; set y [expr {log($e)}]
  set sx [expr {$sx + $x}]; set sy [expr {$sy + $y}]
  set sxx [expr {$sxx + $x * $x}]; set sxy [expr {$sxy + $x * $y}]
}
set slope [expr {($k * $sxy - $sx * $sy) / ($k * $sxx - $sx * $sx)}]
puts [format "observed convergence order (least-squares over n = %s): %.2f" $ns [expr {-$slope}]]
checkTrue "moment error shrinks from 10 to 160 layers by at least 50x ([lindex $errs 0] -> [lindex $errs end])" \
    [expr {[lindex $errs end] < [lindex $errs 0] / 50.0}]
checkTrue [format "observed convergence order >= 1.5 (got %.2f)" [expr {-$slope}]] [expr {-$slope >= 1.5}]
# The finest section matches the closed form closely at every curvature.
check "160 layers: M at 2 phi_y = Mp (1 - 1/12)" [lindex [apply {{} {
  global phiY; buildSection 160; return [pushCurvature [list [expr {2.0 * $phiY}]] [expr {$phiY / 10.0}]]
}}] 0] [expr {$Mp * (1.0 - 1.0 / 12.0)}] 2e-4
check "first yield: M at phi_y = My = fy b h^2/6 (160 layers)" [lindex [apply {{} {
  global phiY; buildSection 160; return [pushCurvature [list $phiY] [expr {$phiY / 10.0}]]
}}] 0] [expr {$fy * $b * $h * $h / 6.0}] 2e-4

# ------------------------------------------------------------------ plastic P-M interaction
# n = 400 layers puts the plastic neutral axis (y = p h/2 for p = P/Py) on a layer boundary for
# p = 0.25, 0.5, 0.75; at phi = 300 phi_y the elastic core is h/300 thick (its moment deficit is
# about (1/3)(1/300)^2 = 4e-6 of Mp) and the two fibers beside the axis stay elastic (strain
# 0.75 eps_y), so the section tangent is not singular.
set kPMTol 2e-4
foreach p {0.0 0.25 0.5 0.75} {
  buildSection 400
  timeSeries Constant 1
  pattern Plain 1 1 { load 2 [expr {-$p * $Py}] 0.0 0.0 }
  integrator LoadControl 1.0
  analysis Static
  set okAxial [expr {[analyze 1] == 0}]
  loadConst -time 0.0
  set m [lindex [pushCurvature [list [expr {300.0 * $phiY}]] [expr {2.0 * $phiY}]] 0]
  checkTrue "P/Py = $p: axial load applied, section still elastic" $okAxial
  check "P/Py = $p: full-plasticity moment M/Mp = 1 - (P/Py)^2" [expr {abs($m) / $Mp}] [expr {1.0 - $p * $p}] $kPMTol
  checkAbs "P/Py = $p: axial force held at -p Py" [lindex [eleResponse 1 force] 3] [expr {-$p * $Py}] [expr {1e-8 * $Py}]
}
finish
