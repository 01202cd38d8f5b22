# SPDX-License-Identifier: MIT
# What the bearing calibration's remaining error does to the bridge case study: runs the three
# cases of verification/bridge/bridge.tcl (no pounding, pounding, countermeasure) with each of the
# given high-damping-rubber sets and prints the peak shear strain of the four bearings on PC2 and
# PC3 (the largest |U|/Tr reached by each, and the largest of the four).
#   dabs verification/bearing/tools/bridge-bearing-sets.tcl name {Y0 U0 n alpha0 beta q gamma} ..
# (parameters per unit area and unit rubber thickness, as in fitted-parameters.md). Several
# minutes of CPU per set: run it under nice.
set here [file dirname [info script]]
set ::bridgeLibraryOnly 1
source [file join $here .. .. bridge bridge.tcl]
if {$argc < 2 || $argc % 2} {
  puts stderr "usage: bridge-bearing-sets.tcl name {Y0 U0 n alpha0 beta q gamma} ?name {..}? .."
  exit 2
}
foreach {name set} $argv {
  set ::hdr $set
  foreach c {nopound pound countermeasure} {
    set r [runCase $c 1.0 $defaultDt $defaultIntegrator $defaultTol auto]
    set peak [dict get $r peak]
    set strains {}
    foreach bt {2011 2012 3011 3012} { lappend strains [format %.3f [dict get $peak strain$bt]] }
    puts [format "%-12s %-15s motion %-6s completed %d  peak shear strain %.3f  (bearings 2011 2012 3011 3012: %s)" \
        $name $c [dict get $r motion] [dict get $r completed] [tcl::mathfunc::max {*}$strains] $strains]
    flush stdout
  }
}
