# SPDX-License-Identifier: MIT
# Integration rules given in the element command (older nIP form with OpenSees' defaults, rules
# written after the transformation tag, HingeRadau) and -lMass/-cMass: runs the input
# verification/opensees/beam-integration.tcl, compares every number with OpenSees 3.8.0's CSV for
# it, and checks the elastic first step against the cantilever closed form 3EI d / L^3.
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] .. lib opensees-csv.tcl]

source [openseesReference beam-integration.tcl]
set r [compareOpenSeesCsv beam-integration.csv [openseesReference beam-integration.csv] 1e-7 1e-10]

# 16 equal strips of a 0.2 x 0.4 section: I (1 - 1/16^2) (midpoint rule).
set EI [expr {2.0e8*0.2*0.4**3/12*(1 - 1.0/256)}]
set L 3.0
foreach case {disp-old disp-old-lobatto disp-inline-list force-old nonlinear-old force-old-legendre
              force-inline-list force-inline-words} {
  check "$case: elastic tip shear 3EI d/L^3 at d = 0.01" [dict get $r $case,shear1] [expr {3*$EI*0.01/$L**3}] 1e-9
}
# Past yield the rule matters: the older dispBeamColumn form integrates with Legendre, not Lobatto.
checkTrue "dispBeamColumn nIP secTag transfTag differs from the same element with Lobatto" \
    [expr {abs([dict get $r disp-old,shear6] - [dict get $r disp-old-lobatto,shear6]) > 1.0}]
check "forceBeamColumn nIP secTag transfTag integrates with Lobatto (as Lobatto secTag nIP)" \
    [dict get $r force-old,shear6] [dict get $r force-inline-words,shear6] 1e-12
finish
