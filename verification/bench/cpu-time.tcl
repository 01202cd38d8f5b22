# SPDX-License-Identifier: MIT
# CPU seconds of this process (user + system, from /proc/self/stat), for the benchmarks that
# quote CPU time beside wall time on a shared machine.
proc cpuSeconds {} {
  # after the command name in parentheses (which may hold spaces): the state is field 3, utime
  # and stime are fields 14 and 15 (1-based), in clock ticks of 1/100 s
  set f [open /proc/self/stat]; set fields [split [lindex [split [read $f] ")"] end]]; close $f
  return [expr {([lindex $fields 12] + [lindex $fields 13]) / 100.0}]
}

# The process's CPU time sums every thread's, so a benchmark that quotes it runs on one thread:
# the automatic choice (`threads auto`, the default) may take two on a large model, and their
# time (and the second thread's wait) would count twice.
threads 1
