# SPDX-License-Identifier: MIT
# `integrator HSConstraint s psiU psiF uRef` with psiU = uRef = 1 and psiF = 0 constrains the same
# quantity as `integrator ArcLength s 0` (dU.dU = s^2), so dabs must trace the path OpenSees 3.8
# traced with ArcLength for the arch of compat-arclength.tcl (the first block of its CSV). OpenSees'
# own HSConstraint is not the reference: it solves its quadratic with a discriminant off by a
# factor, converges linearly and, on this arch, to the backward intersection of the constraint.
source [file join [file dirname [info script]] .. lib check.tcl]
set arcLengthCases {{1e-10 HSConstraint 0.02 1.0 0.0 1.0}}
source [openseesReference compat-arclength.tcl]
set f [open compat-arclength.out]; set ours [split [string trim [read $f]] \n]; close $f
set f [open [openseesReference compat-arclength.csv]]; set theirs [split [string trim [read $f]] \n]; close $f
set theirs [lrange $theirs 1 40]
checkTrue "HSConstraint: 40 steps as OpenSees' ArcLength ([expr {[llength $ours] - 1}])" [expr {[llength $ours] == 41}]
set worst 0.0
foreach a [lrange $ours 1 end] b $theirs {
  foreach x $a y $b scale {1.5 0.75 0.25} {
    set worst [expr {max($worst, abs($x - $y) / $scale)}]
  }
}
checkAbs "HSConstraint path vs OpenSees ArcLength, largest difference / column scale" $worst 0.0 1e-6
finish
