# SPDX-License-Identifier: MIT
# Shared by the benchmark models (plain Tcl, so dabs and OpenSees run the same code).
#
# timedAnalyze label args: runs `analyze args`, prints "label status=.. analyze_s=.." (the line
# compare.sh reads) and, in dabs, the work counts of analysisStatistics.
proc timedAnalyze {label args} {
  set t0 [clock milliseconds]
  set ok [analyze {*}$args]
  set wall [expr {([clock milliseconds] - $t0)/1000.0}]
  puts "$label status=$ok analyze_s=$wall"
  if {[info commands analysisStatistics] ne ""} { puts "counts [analysisStatistics]" }
  return $ok
}

# Reads a PEER NGA .AT2 record (header lines, then `NPTS= n, DT= dt SEC`, then values in g, up
# to a trailer such as `*** End data ***` if there is one) and
# writes its values one a line to a plain file that `timeSeries Path -filePath` reads in any
# OpenSees-compatible program. Plain Tcl, so dabs and OpenSees run the same code.
#
#   set dt [writePlainRecord in.AT2 out.txt]   ;# returns the record's time step

set ::benchRecordDir [file dirname [file normalize [info script]]]

proc findRecord {name} {
  set f [file normalize [file join $::benchRecordDir .. .. data $name]]
  if {![file exists $f]} { error "record $name not found in verification/data" }
  return $f
}

proc writePlainRecord {at2 out} {
  set in [open $at2 r]
  set dt ""
  set values {}
  while {[gets $in line] >= 0} {
    if {$dt eq ""} {
      if {[regexp -nocase {NPTS\s*=\s*([0-9]+)\s*,\s*DT\s*=\s*([0-9.Ee+-]+)} $line -> npts dt]} { continue }
      continue
    }
    foreach v $line {
      if {![string is double -strict $v]} { break }
      lappend values $v
    }
  }
  close $in
  if {$dt eq ""} { error "$at2: no `NPTS= .., DT= ..` header line" }
  set f [open $out w]
  foreach v $values { puts $f $v }
  close $f
  return [expr {double($dt)}]
}
