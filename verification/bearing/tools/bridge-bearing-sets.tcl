# SPDX-License-Identifier: MIT
# What the bearing calibration's remaining error does to the bridge case study: runs the three
# cases of verification/bridge/bridge.tcl (no pounding, pounding, countermeasure) with each of the
# given high-damping-rubber sets and prints the peak shear strain of the four bearings on PC2 and
# PC3 (the largest |U|/Tr reached by each, and the largest of the four) and the impacts.
#   dabs verification/bearing/tools/bridge-bearing-sets.tcl ?-scale s? name {Y0 U0 n alpha0 beta q gamma} ..
# (s scales the ground motion, default 1).
# (parameters per unit area and unit rubber thickness, as in fitted-parameters.md). Several
# minutes of CPU per set: run it under nice.
set here [file dirname [info script]]
set ::bridgeLibraryOnly 1
source [file join $here .. .. bridge bridge.tcl]
set motionScale 1.0
if {[lindex $argv 0] eq "-scale"} {
  set motionScale [lindex $argv 1]
  set argv [lrange $argv 2 end]
  set argc [llength $argv]
}
if {$argc < 2 || $argc % 2} {
  puts stderr "usage: bridge-bearing-sets.tcl ?-scale s? name {Y0 U0 n alpha0 beta q gamma} ?name {..}? .."
  exit 2
}
foreach {name set} $argv {
  set ::hdr $set
  foreach c {nopound pound countermeasure} {
    set r [runCase $c $motionScale $defaultDt $defaultIntegrator $defaultTol auto]
    set peak [dict get $r peak]
    set strains {}
    foreach bt {2011 2012 3011 3012} { lappend strains [format %.3f [dict get $peak strain$bt]] }
    puts [format "%-10s x%-4s %-15s %s completed %d impacts %-7s peak shear strain %.3f (bearings 2011 2012 3011 3012: %s)" \
        $name $motionScale $c [dict get $r motion] [dict get $r completed] [join [dict get $r impacts] /] \
        [tcl::mathfunc::max {*}$strains] $strains]
    flush stdout
  }
}
