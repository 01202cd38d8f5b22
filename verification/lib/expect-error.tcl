# SPDX-License-Identifier: MIT
# Checks of bad input: the Tcl error and its message, and a model left as it was.

# Expects `script` to raise a Tcl error whose message contains every word in `words`.
proc expectError {label script words} {
  set rc [catch {uplevel 1 $script} msg]
  if {$rc != 1} {
    checkTrue "$label: raises a Tcl error (got code $rc, result \"$msg\")" 0
    return
  }
  set missing {}
  foreach w $words { if {[string first [string tolower $w] [string tolower $msg]] < 0} { lappend missing $w } }
  checkTrue "$label: error names [join $words {, }] (message: $msg)" [expr {[llength $missing] == 0}]
}
proc modelState {} { list [lsort -integer [getNodeTags]] [lsort -integer [getEleTags]] }
proc expectUnchanged {label before} {
  set after [modelState]
  checkTrue "$label: model unchanged (nodes/elements [lindex $after 0] / [lindex $after 1])" [expr {$after eq $before}]
}

