# SPDX-License-Identifier: MIT
# getPID, getNP, barrier, send, recv, Bcast and `ensemble run`: what they return and how they
# report bad input, on one process (dabs) and on several (mpirun -n 2 dabs-mp).
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] .. lib expect-error.tcl]

set pid [getPID]
set np [getNP]
checkTrue "getNP is at least 1 (got $np)" [expr {$np >= 1}]
checkTrue "getPID is from 0 to getNP - 1 (got $pid)" [expr {$pid >= 0 && $pid < $np}]
barrier

# Bcast: every process gets process 0's value; several values travel as a list.
set b [Bcast "from [getPID]" ]
checkTrue "Bcast returns process 0's value on every process (got \"$b\")" [expr {$b eq "from 0"}]
set b [Bcast 1.5 2.5 3.5]
checkTrue "Bcast of several values returns their list (got \"$b\")" [expr {$b eq "1.5 2.5 3.5"}]

# Point to point: everyone sends its number to 0, which sums them; then 0's broadcast form.
if {$pid == 0} {
  set sum 0
  for {set p 1} {$p < $np} {incr p} {
    set from [recv -pid $p value]
    checkTrue "recv -pid $p returns the sender ($from)" [expr {$from == $p}]
    incr sum $value
  }
  checkTrue "sum of the process numbers is NP(NP-1)/2" [expr {$sum == $np * ($np - 1) / 2}]
  if {$np > 1} { send "a value with spaces, {braces} and \"quotes\"" }
} else {
  send -pid 0 $pid
  recv text
  checkTrue "recv without -pid takes what process 0 sent (\"$text\")" \
      [expr {$text eq "a value with spaces, {braces} and \"quotes\""}]
}

# Bad input, on every process (none of these reaches another process).
expectError "send to itself" { send -pid [getPID] 1 } {send -pid "other than this process"}
expectError "send to a process that does not exist" { send -pid $np 1 } {send -pid expected}
expectError "send to a non-number" { send -pid two 1 } {send -pid "process number" two}
expectError "recv from itself" { recv -pid [getPID] v } {recv -pid}
expectError "send without a value" { send -pid 0 } {send value}
if {$pid == 0} {
  expectError "recv without -pid on process 0" { recv v } {recv "process 0"}
  expectError "Bcast without a value on process 0" { Bcast } {Bcast value}
} else {
  expectError "send without -pid on another process" { send 1 } {send "only process 0"}
}
if {$np == 1} {
  expectError "one process has nobody to send to" { send -pid 1 x } {send "the only one" "getNP is 1"}
  expectError "one process has nobody to receive from" { recv -pid ANY x } {recv "no other process" "getNP is 1"}
}
expectError "ensemble needs run" { ensemble go {} x } {ensemble subcommand run go}
expectError "ensemble: a job is a dict" { ensemble run {{a 1 b}} job } {"ensemble run" jobList "job 1" dict}
expectError "ensemble: ids name files" { ensemble run {{id a/b}} job } {"ensemble run" "a/b" letters}
expectError "ensemble: ids are unique" { ensemble run {{id a} {id a}} job } {"ensemble run" twice}
expectError "ensemble: reserved column" { ensemble run {{status 1}} job } {"ensemble run" status column}
expectError "ensemble: unknown option" { ensemble run {} job -output x } {"ensemble run" -output}

# Inside a job the script's own messages and a nested ensemble are refused; the job records the
# error and the ensemble goes on.
proc nested {job} {
  dict with job {}
  switch -- $what {
    send { send -pid 0 1 }
    barrier { barrier }
    ensemble { ensemble run {{x 1}} nested }
    result { return [list value [expr {$x * 2}] code 0] }
    odd { return {a 1 b} }
    clash { return [list x 3] }
  }
}
set jobs {{id j1 what send} {id j2 what barrier} {id j3 what ensemble} {id j4 what result x 21}
          {id j5 what odd} {id j6 what clash x 1}}
set summary [ensemble run $jobs nested -out commands-out]
checkTrue "ensemble summary counts 1 ok and 5 errors ($summary)" \
    [expr {[dict get $summary ok] == 1 && [dict get $summary error] == 5 && [dict get $summary jobs] == 6}]
if {$pid == 0} {
  set fh [open [dict get $summary file]]; set merged [read $fh]; close $fh
  foreach {id words} {j1 "not available inside an ensemble job" j2 "not available inside an ensemble job"
                      j3 "cannot run an ensemble" j5 "expected a dict of results" j6 "repeats a job parameter"} {
    checkTrue "job $id recorded with \"$words\"" [regexp "\n$id,error,,\[^\n\]*$words" $merged]
  }
  checkTrue "job j4 recorded with its result" [regexp {\nj4,ok,0,,[0-9]+,[0-9.]+,j4,result,21,42\n} $merged]
}
finish
