# SPDX-License-Identifier: MIT
# Runs one of the compatibility inputs (compat-*.tcl) in dabs and compares the table it writes,
# <name>.out in the working directory, with <name>.csv beside the input, which OpenSees 3.8.0 wrote
# from the same input. Usage: dabs compare.tcl input.tcl ?relTol?
# Each number is compared with OpenSees' to relTol (default 1e-6) of the largest magnitude in its
# column, so near-zero entries of a column are held to the column's scale. A line that does not
# start with a number (a header) starts a new block with scales of its own.
source [file join [file dirname [info script]] .. lib check.tcl]

proc ::verify::readTable {path} {
  set f [open $path]
  set rows {}
  set block 0
  while {[gets $f line] >= 0} {
    set line [string trim [string map {, " "} $line]]
    if {$line eq ""} continue
    if {![string is double -strict [lindex $line 0]]} { incr block; continue }
    lappend rows [linsert $line 0 $block]
  }
  close $f
  return $rows
}

proc ::verify::compareTables {name ours theirs tol} {
  checkTrue "$name: same number of rows ([llength $ours] in dabs, [llength $theirs] in OpenSees)" \
    [expr {[llength $ours] == [llength $theirs]}]
  array set scale {}
  foreach row $theirs {
    set block [lindex $row 0]
    set i 0
    foreach v $row {
      if {![info exists scale($block,$i)]} { set scale($block,$i) 0.0 }
      set scale($block,$i) [expr {max($scale($block,$i), abs($v))}]
      incr i
    }
  }
  set worst 0.0; set where ""
  set n 0
  foreach a $ours b $theirs {
    incr n
    if {[llength $a] != [llength $b]} {
      checkTrue "$name: row $n has [llength $b] columns as in OpenSees (dabs [llength $a])" 0
      return
    }
    set block [lindex $b 0]
    set i 0
    foreach x $a y $b {
      set s [expr {[info exists scale($block,$i)] ? max($scale($block,$i), 1e-300) : 1.0}]
      set err [expr {abs($x - $y) / $s}]
      if {$err > $worst} { set worst $err; set where "row $n column $i: dabs $x, OpenSees $y" }
      incr i
    }
  }
  checkAbs "$name: largest difference / column scale ($where)" $worst 0.0 $tol
}

# The input runs at global level, so the driver keeps its own names in its namespace.
set ::verify::input [file normalize [lindex $argv 0]]
set ::verify::tol [expr {[llength $argv] > 1 ? [lindex $argv 1] : 1e-6}]
set ::verify::name [file rootname [file tail $::verify::input]]
file delete $::verify::name.out
source $::verify::input
::verify::compareTables $::verify::name [::verify::readTable $::verify::name.out] \
  [::verify::readTable [file join [file dirname $::verify::input] $::verify::name.csv]] $::verify::tol
finish
