# SPDX-License-Identifier: MIT
# The results table an `ensemble run` writes (dir/results.csv: a header, one row a job), read back
# as a list of dicts column -> value. Only error messages are quoted in that file, and a study
# reads the numbers of completed jobs, so a quoted cell is dropped before the row is split.
#
#   source results.tcl
#   ensembleResults::read file   -> {row row ...}, each a dict (job, status, code, ..., results)

namespace eval ensembleResults {}

proc ensembleResults::read {file} {
  set fh [open $file]; set lines [split [string trimright [::read $fh] \n] \n]; close $fh
  set header [split [lindex $lines 0] ,]
  set rows {}
  foreach line [lrange $lines 1 end] {
    if {[string first \" $line] >= 0} { set line [regsub -all {"[^"]*"} $line {}] }
    set row {}
    foreach k $header v [split $line ,] { dict set row $k $v }
    lappend rows $row
  }
  return $rows
}
