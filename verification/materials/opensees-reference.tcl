# SPDX-License-Identifier: MIT
# Runs OpenSees' own input verification/opensees/materials.tcl unchanged through dabs
# and compares every strain, stress and tangent with the CSV files OpenSees 3.8.0 wrote for it.
source [file join [file dirname [info script]] .. lib check.tcl]

set reference [file dirname [openseesReference materials.tcl]]
source [file join $reference materials.tcl]   ;# writes <name>.csv in the working directory

proc readCsv {path} {
  set f [open $path]
  gets $f header
  set rows {}
  while {[gets $f line] >= 0} { if {$line ne ""} { lappend rows [split $line ,] } }
  close $f
  return $rows
}

# The CSVs hold 10 significant digits; compare to 1e-8 of the column's scale.
foreach name {steel01 steel02 steel02-isohard concrete01 concrete02 eppgap-compression eppgap-tension-damage} {
  set ours [readCsv $name.csv]
  set theirs [readCsv [file join $reference $name.csv]]
  checkTrue "$name: same number of points ([llength $ours] vs [llength $theirs])" [expr {[llength $ours] == [llength $theirs]}]
  set stressScale 0.0; set tangentScale 0.0
  foreach row $theirs {
    set stressScale [expr {max($stressScale, abs([lindex $row 1]))}]
    set tangentScale [expr {max($tangentScale, abs([lindex $row 2]))}]
  }
  set worstStress 0.0; set worstTangent 0.0
  foreach a $ours b $theirs {
    set worstStress [expr {max($worstStress, abs([lindex $a 1] - [lindex $b 1]))}]
    set worstTangent [expr {max($worstTangent, abs([lindex $a 2] - [lindex $b 2]))}]
  }
  checkAbs "$name: largest stress difference / max |stress| (OpenSees 3.8.0)" [expr {$worstStress/$stressScale}] 0.0 1e-8
  checkAbs "$name: largest tangent difference / max |tangent| (OpenSees 3.8.0)" [expr {$worstTangent/$tangentScale}] 0.0 1e-8
}
finish
