# SPDX-License-Identifier: MIT
# Trusses on a section and the corotational truss: runs the input
# verification/opensees/truss-section-corot.tcl, compares every number with OpenSees 3.8.0's CSV
# for it, and checks closed forms: the section truss equals the A-matTag truss, the von Mises
# truss follows the exact equilibrium of its apex at every step through snap-through, and the
# bar periods are 2 pi sqrt(m/k) with the lumped (rho L/2) and consistent (rho L/3) end mass.
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] .. lib opensees-csv.tcl]

source [openseesReference truss-section-corot.tcl]
set r [compareOpenSeesCsv truss-section-corot.csv [openseesReference truss-section-corot.csv] 1e-7 1e-10]

foreach k {3 6 10} {
  check "section truss = A matTag truss, axial force at step $k" [dict get $r truss-section,N$k] [dict get $r truss-material,N$k] 1e-12
}
# Von Mises truss: apex at height y = h + w, bar length l, N = EA (l - L)/L (engineering strain),
# vertical equilibrium lambda = -2 N y / l under the downward reference load.
set a 2.0; set h 0.2; set EA [expr {2.0e8*0.001}]; set L [expr {hypot($a, $h)}]
set worstN 0.0; set worstP 0.0
for {set k 1} {$k <= 25} {incr k} {
  set y [expr {$h + [dict get $r vonmises,w$k]}]
  set l [expr {hypot($a, $y)}]
  set N [expr {$EA*($l - $L)/$L}]
  set worstN [expr {max($worstN, abs([dict get $r vonmises,N$k] - $N))}]
  set worstP [expr {max($worstP, abs([dict get $r vonmises,P$k] + 2*$N*$y/$l))}]
}
checkAbs "von Mises truss: bar force EA (l - L)/L at every step (kN)" $worstN 0.0 1e-8
checkAbs "von Mises truss: apex equilibrium lambda = -2 N y / l at every step (kN)" $worstP 0.0 1e-8
checkTrue "von Mises truss passes its snap-through (the load reverses)" \
    [expr {[dict get $r vonmises,P5] * [dict get $r vonmises,P15] < 0}]
set k [expr {0.01*2.0e8/2.0}]
check "bar period, lumped mass rho L/2" [dict get $r bar-lumped,period] [expr {2*acos(-1)*sqrt(7.85*2.0/2/$k)}] 1e-10
check "bar period, consistent mass rho L/3" [dict get $r bar-consistent,period] [expr {2*acos(-1)*sqrt(7.85*2.0/3/$k)}] 1e-10
check "section truss with -rho -cMass" [dict get $r bar-truss-cmass,period] [expr {2*acos(-1)*sqrt(7.85*2.0/3/$k)}] 1e-10
finish
