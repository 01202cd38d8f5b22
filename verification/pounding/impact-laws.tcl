# SPDX-License-Identifier: MIT
# Two masses colliding head-on through a nodeToSurface pair with each impact law (-law kelvin,
# hertz, hertzdamp, jankowski), Newmark average acceleration and Newton at about 200 steps per
# contact. Reference: this script's own RK4 integration of the relative motion
# m x'' = -N(x, x'), m = M1 M2 / (M1 + M2), x the penetration, N written here from each law's
# published formula (Zhu, Abe and Fujino 2002; Hertz; Muthukumar and DesRoches 2006 with the
# Lankarani and Nikravesh 1990 damping; Jankowski 2005 with his 2006 xi(e)). Checks: restitution
# within 2 % of the reference, momentum conserved, no kinetic energy gained.
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] lib contact.tcl]

set M1 2.0       ;# contactor mass
set M2 3.0       ;# target mass (four nodes of M2/4)
set mred [expr {$M1*$M2/($M1+$M2)}]
set gap0 0.005

# Normal force of each law at penetration x > 0 and rate xd (compression positive).
proc lawForce {law params x xd} {
  global mred
  dict with params {}
  switch -- $law {
    kelvin {
      set xi [dampingRatio $e]
      set C [expr {2*$xi*sqrt($K*$mred)}]
      return [expr {max(0.0, $K*$x + $C*$xd)}]
    }
    hertz { return [expr {$K*pow($x, $n)}] }
    hertzdamp {
      set ch [expr {3*$K*(1 - $e*$e)/(4*$v0)}]
      return [expr {max(0.0, $K*pow($x, $n) + $ch*pow($x, $n)*$xd)}]
    }
    jankowski {
      set xi [expr {9*sqrt(5)*(1 - $e*$e)/(2*$e*($e*(9*$::pi - 16) + 16))}]
      set f [expr {$K*pow($x, 1.5)}]
      if {$xd > 0} { set f [expr {$f + 2*$xi*sqrt($K*sqrt($x)*$mred)*$xd}] }
      return $f
    }
  }
}

# Elastic exponent of a law (1 for kelvin).
proc exponent {law params} {
  if {$law eq "kelvin"} { return 1.0 }
  if {$law eq "jankowski"} { return 1.5 }
  return [dict get $params n]
}

# Contact duration estimate: the elastic one (pi/w for kelvin, 2.94 x_max / v for n = 1.5).
proc contactTime {law params v} {
  global mred
  set K [dict get $params K]
  set n [exponent $law $params]
  set xmax [expr {pow(0.5*($n + 1)*$mred*$v*$v/$K, 1.0/($n + 1))}]
  return [expr {3.0*$xmax/$v}]
}

# Restitution by RK4 of m x'' = -N(x, x') from x = 0, x' = v until x returns to 0.
proc referenceRestitution {law params v} {
  global mred
  set h [expr {[contactTime $law $params $v]/20000.0}]
  set x 0.0; set xd $v
  for {set i 0} {$i < 1000000} {incr i} {
    set ax  [expr {-[lawForce $law $params [expr {max($x, 0.0)}] $xd]/$mred}]
    set x2 [expr {$x + 0.5*$h*$xd}]; set v2 [expr {$xd + 0.5*$h*$ax}]
    set a2 [expr {-[lawForce $law $params [expr {max($x2, 0.0)}] $v2]/$mred}]
    set x3 [expr {$x + 0.5*$h*$v2}]; set v3 [expr {$xd + 0.5*$h*$a2}]
    set a3 [expr {-[lawForce $law $params [expr {max($x3, 0.0)}] $v3]/$mred}]
    set x4 [expr {$x + $h*$v3}]; set v4 [expr {$xd + $h*$a3}]
    set a4 [expr {-[lawForce $law $params [expr {max($x4, 0.0)}] $v4]/$mred}]
    set xn [expr {$x + $h/6*($xd + 2*$v2 + 2*$v3 + $v4)}]
    set vn [expr {$xd + $h/6*($ax + 2*$a2 + 2*$a3 + $a4)}]
    if {$xn < 0 && $vn < 0} { return [expr {-($xd + ($vn - $xd)*$x/($x - $xn))/$v}] }
    set x $xn; set xd $vn
  }
  error "no separation"
}

# The impact through the program: {v1 v2 v1' v2' failed}.
proc impact {law params v} {
  global M1 M2 gap0
  wipe
  model basic -ndm 3 -ndf 3
  node 1 -1 -1 0; node 2 1 -1 0; node 3 1 1 0; node 4 -1 1 0
  node 5 0 0 $gap0
  foreach n_ {1 2 3 4 5} { fix $n_ 1 1 0 }
  foreach n_ {1 2 3 4} { mass $n_ 0 0 [expr {$M2/4.0}] }
  mass 5 0 0 $M1
  set opts [list -law $law -masses $M1 $M2]
  dict for {key value} $params { lappend opts -$key $value }
  element nodeToSurface 1 5 1 2 3 4 {*}$opts
  set dt [expr {[contactTime $law $params $v]/200.0}]
  set tp [expr {ceil(0.002/$dt)*$dt}]
  timeSeries Constant 1
  pattern Plain 1 1 { load 5 0 0 [expr {-$M1*$v/$tp}] }
  constraints Plain; numberer Plain; system FullGeneral
  test NormDispIncr 1e-12 50; algorithm Newton
  integrator Newmark 0.5 0.25; analysis Transient
  set failed [runUntil $dt $tp]
  remove loadPattern 1
  incr failed [runUntil $dt [expr {$tp + $dt}]]
  set v1 [nodeVel 5 3]; set v2 [nodeVel 1 3]
  incr failed [runUntil $dt [expr {$tp + 0.2}] {expr {[lindex [eleResponse 1 impulse] 0] > 0 && [lindex [eleResponse 1 gap] 0] > 0}}]
  return [list $v1 $v2 [nodeVel 5 3] [nodeVel 1 3] $failed]
}

set cases {
  kelvin    {K 1e6 e 0.6}                 {1.0}
  hertz     {K 1e9 n 1.5}                 {1.0}
  hertzdamp {K 1e9 n 1.5 e 0.7 v0 1.0}    {1.0 2.0}
  jankowski {K 1e9 e 0.65}                {0.5 1.5}
}
set rows {}
foreach {law params speeds} $cases {
  foreach v $speeds {
    lassign [impact $law $params $v] v1 v2 u1 u2 failed
    checkTrue "$law v=$v: every step converged" [expr {$failed == 0}]
    set p0 [expr {$M1*$v1 + $M2*$v2}]
    set p1 [expr {$M1*$u1 + $M2*$u2}]
    checkAbs "$law v=$v: momentum conserved" $p1 $p0 [expr {1e-8*abs($p0)}]
    set eProgram [expr {-($u1 - $u2)/($v1 - $v2)}]
    set eReference [referenceRestitution $law $params [expr {$v2 - $v1}]]
    check "$law v=$v: restitution against RK4" $eProgram $eReference 0.02
    set before [expr {0.5*$M1*$v1*$v1 + 0.5*$M2*$v2*$v2}]
    set after [expr {0.5*$M1*$u1*$u1 + 0.5*$M2*$u2*$u2}]
    checkTrue "$law v=$v: no energy gained ([format %.3e [expr {$after/$before - 1}]])" \
        [expr {$after <= $before*(1 + 1e-9)}]
    lappend rows [list $law $params [expr {$v2 - $v1}] $eProgram $eReference [expr {$before - $after}]]
  }
}
puts ""
puts [format "%-10s %-26s %6s %10s %10s %12s" law parameters v "e program" "e RK4" "energy lost"]
foreach r $rows {
  lassign $r law params v ep er lost
  puts [format "%-10s %-26s %6.3f %10.5f %10.5f %12.5g" $law $params $v $ep $er $lost]
}
finish
