# SPDX-License-Identifier: MIT
# Rayleigh damping with the committed tangent (betaKcomm) on yielding force- and
# displacement-based beams: runs the input verification/opensees/rayleigh-committed.tcl and compares
# every displacement and shear with OpenSees 3.8.0's CSV for it. The same run with the initial
# stiffness in place of the committed one (what betaKcomm once fell back to for beams) moves the
# peak drift by several per cent, so the comparison tells the two apart.
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] .. lib opensees-csv.tcl]

source [openseesReference rayleigh-committed.tcl]
set r [compareOpenSeesCsv rayleigh-committed.csv [openseesReference rayleigh-committed.csv] 1e-7 1e-10]
finish
