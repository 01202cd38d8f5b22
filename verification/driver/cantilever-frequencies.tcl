# SPDX-License-Identifier: MIT
# Natural frequencies of a uniform cantilever and of a portal frame (eigen).
#
# Sources:
# - Euler-Bernoulli cantilever: omega_n = (beta_n L)^2 sqrt(E I / (mbar L^4)) with
#   beta_n L = 1.875104, 4.694091, 7.854757 (roots of cos x cosh x = -1); Chopra, Dynamics of
#   Structures (4th ed.), §16.3 (Example 16.2 / Table 16.3.1) and Clough & Penzien §18-3.
#   Consistent mass with the exact-static cubic shape functions is a Rayleigh-Ritz model, so its
#   frequencies are upper bounds and converge from above (Clough & Penzien §16-5; Chopra §17.5).
# - Portal frame, fixed bases, columns h (E Ic), girder Lb (E Ib), mass m at the girder, axial
#   deformation negligible: slope-deflection with antisymmetric joint rotation gives
#   k = (24 a / h^2) (a + 6 b) / (4 a + 6 b), a = E Ic / h, b = E Ib / Lb
#   (the same as Chopra eq. 1.3.5 / Example 1.1 with his rho); rigid girder: k = 24 E Ic / h^3;
#   omega^2 = k / m (Chopra §2.1).
source [file join [file dirname [info script]] .. lib check.tcl]

set TOL_N20 0.005      ;# brief: N = 20 within 0.5 % for mode 1
set TOL_PORTAL 1e-6    ;# single exact elements per member; A large enough that axial strain is ~1e-7
set TOL_RIGID 1e-3     ;# girder 1e4 times stiffer than the columns: (a+6b)/(4a+6b) = 1 - 1.2e-4

set betaL {1.875104069 4.694091133 7.854757438}
set L 2.0; set E 1.0e4; set I 1.0e-2; set A 100.0; set mbar 1.0

proc exactOmega {n} {
  set b [lindex $::betaL [expr {$n - 1}]]
  return [expr {$b * $b * sqrt($::E * $::I / ($::mbar * $::L ** 4))}]
}

# Returns the first three circular frequencies of the cantilever with n elements.
proc cantilever {n massType} {
  wipe
  model basic -ndm 2 -ndf 3
  for {set i 0} {$i <= $n} {incr i} { node [expr {$i + 1}] [expr {$::L * $i / $n}] 0.0 }
  fix 1 1 1 1
  geomTransf Linear 1
  for {set i 1} {$i <= $n} {incr i} {
    if {$massType eq "consistent"} {
      element elasticBeamColumn $i $i [expr {$i + 1}] $::A $::E $::I 1 -mass $::mbar -cMass
    } else {
      element elasticBeamColumn $i $i [expr {$i + 1}] $::A $::E $::I 1 -mass $::mbar
    }
  }
  set lambdas [eigen 3]
  return [lmap l $lambdas {expr {sqrt($l)}}]
}

foreach massType {consistent lumped} {
  set previous {}
  foreach n {3 6 12 20} {
    set w [cantilever $n $massType]
    set errors {}
    for {set mode 1} {$mode <= 3} {incr mode} {
      set we [exactOmega $mode]
      set wc [lindex $w [expr {$mode - 1}]]
      lappend errors [expr {abs($wc - $we) / $we}]
      if {$massType eq "consistent"} {
        checkTrue [format "cantilever consistent mass N=%d mode %d: omega %.6g >= exact %.6g (Rayleigh-Ritz upper bound)" \
                     $n $mode $wc $we] [expr {$wc >= $we * (1.0 - 1e-12)}]
      }
    }
    if {$previous ne ""} {
      for {set mode 1} {$mode <= 3} {incr mode} {
        set e0 [lindex $previous [expr {$mode - 1}]]
        set e1 [lindex $errors [expr {$mode - 1}]]
        checkTrue [format "cantilever %s mass mode %d: error shrinks with N (%.3e -> %.3e at N=%d)" \
                     $massType $mode $e0 $e1 $n] [expr {$e1 < $e0}]
      }
    }
    set previous $errors
  }
  check "cantilever $massType mass N=20 mode 1 vs beta1 L = 1.8751 (Chopra §16.3)" \
    [lindex $w 0] [exactOmega 1] $TOL_N20
}

# ---------------------------------------------------------------- portal frame
proc portal {h Lb Ec Ic Ib m} {
  wipe
  model basic -ndm 2 -ndf 3
  node 1 0.0 0.0
  node 2 $Lb 0.0
  node 3 0.0 $h -mass [expr {$m / 2.0}] 0.0 0.0
  node 4 $Lb $h -mass [expr {$m / 2.0}] 0.0 0.0
  fix 1 1 1 1
  fix 2 1 1 1
  geomTransf Linear 1
  set Abig 1.0e3
  element elasticBeamColumn 1 1 3 $Abig $Ec $Ic 1
  element elasticBeamColumn 2 2 4 $Abig $Ec $Ic 1
  element elasticBeamColumn 3 3 4 $Abig $Ec $Ib 1
  return [lindex [eigen 1] 0]
}
set h 3.0; set Lb 6.0; set Ec 2.0e4; set Ic 1.0e-3; set m 2.5
foreach {label Ib tol} [list "girder Ib = Ic" $Ic $TOL_PORTAL "girder Ib = 3 Ic" [expr {3.0 * $Ic}] $TOL_PORTAL] {
  set a [expr {$Ec * $Ic / $h}]
  set b [expr {$Ec * $Ib / $Lb}]
  set k [expr {24.0 * $a / ($h * $h) * ($a + 6.0 * $b) / (4.0 * $a + 6.0 * $b)}]
  check "portal frame ($label): omega^2 = k/m, k by slope-deflection" [portal $h $Lb $Ec $Ic $Ib $m] [expr {$k / $m}] $tol
}
check "portal frame, stiff girder (Ib = 1e4 Ic): omega^2 = 24 E Ic / (h^3 m) (Chopra §1.3)" \
  [portal $h $Lb $Ec $Ic [expr {1.0e4 * $Ic}] $m] [expr {24.0 * $Ec * $Ic / ($h ** 3 * $m)}] $TOL_RIGID
wipe
finish
