# SPDX-License-Identifier: MIT
# Far contact pairs sleep (out of the matrix pattern and the iterations, checked once per step)
# and wake when they come near: the result must be the one of the same pairs evaluated at every
# iteration. Two girder-end faces (2 x 1 m and 3 x 2 m, 4 nodes each, on elastic springs, the
# second face's nodes four times as heavy, so the faces swing at different periods) start 0.05 m apart
# and are shaken along the row; they close, pound and open again several times. Run 1: pounding
# pairs with a search distance of 0.01 m (asleep while apart); run 2: no search distance. The
# displacements and contact forces must agree at every step to round-off (the two runs order the
# factorisation differently while the pairs sleep), and the sleeping run must have changed its
# matrix pattern (pairs fell asleep and woke). For each impact law: kelvin (K 1e4 kN/m), hertz and
# jankowski (k_h 1.8e5 kN/m^1.5, about 1e4 kN/m over the few millimetres the faces close, jankowski
# with e 0.5 and masses 1 t and 16 t), so that a power law's pair sleeps and wakes alike.
set failures 0
proc check {name ok {detail ""}} {
  if {$ok} { puts "PASSED $name" } else { puts "FAILED $name $detail"; incr ::failures }
}

proc build {search} {
  wipe
  model basic -ndm 3 -ndf 3
  uniaxialMaterial Elastic 1 100.0
  set ele 0
  # the second face is larger (3 x 2 m), so the first face's corners meet it inside its edges
  foreach side {0 1} m {1.0 4.0} w {1.0 1.5} d {0.5 1.0} {
    set x [expr {0.05 * $side}]
    set i 0
    foreach {y z} [list -$w -$d $w -$d $w $d -$w $d] {
      incr i
      set n [expr {100 * $side + $i}]
      node $n $x $y $z
      node [expr {$n + 50}] $x $y $z
      fix [expr {$n + 50}] 1 1 1
      mass $n $m $m $m
      element zeroLength [incr ele] [expr {$n + 50}] $n -mat 1 1 1 -dir 1 2 3
    }
  }
  set opts $::lawOptions
  if {$search > 0} { lappend opts -search $search }
  set ::pairs [pounding 1000 -side1 {1 2 3 4} {1 2 3 4} -side2 {101 102 103 104} {101 104 103 102} {*}$opts]
  timeSeries Trig 1 0.0 100.0 0.8 -factor 3.0
  pattern UniformExcitation 1 1 -accel 1
  constraints Plain; numberer RCM; system UmfPack
  test NormDispIncr 1e-9 30; algorithm Newton
  integrator Newmark 0.5 0.25; analysis Transient
}
proc run {search} {
  build $search
  set rows {}
  for {set k 0} {$k < 800} {incr k} {
    if {[analyze 1 0.005] != 0} { return [list $rows fail] }
    set f 0.0
    foreach e $::pairs { set f [expr {$f + [lindex [eleResponse $e contactForce] 0]}] }
    lappend rows [list [nodeDisp 1 1] [nodeDisp 101 1] $f]
  }
  set ::redone [dict get [contactStepping] redoneSteps]
  return [list $rows [dict get [contactStepping] patternChanges]]
}
foreach {law ::lawOptions} {
  kelvin {-K 1.0e4}
  hertz {-law hertz -K 1.8e5 -Kt 1.0e4}
  jankowski {-law jankowski -K 1.8e5 -e 0.5 -masses 1.0 16.0 -Kt 1.0e4}
} {
puts "--- $law"
lassign [run 0] allRows none
check "$law: the run without search completes and never changes its pattern" [expr {$none == 0}] $none
# 0.01 m: pairs wake as they come within it, before touching; 0.001 m: less than the faces close
# in one step (about 6 mm), so a sleeper can be found in contact after a step, which is redone.
foreach search {0.01 0.001} {
  lassign [run $search] sleepRows changes
  set redone $::redone
  check "$law, search $search: the run completes" [expr {$changes ne "fail"}]
  set worstU 0.0; set worstF 0.0; set peakU 0.0; set peakF 0.0; set impacts 0; set closed 0
  foreach a $sleepRows b $allRows {
    lassign $a u1 u2 f; lassign $b v1 v2 g
    set peakU [expr {max($peakU, abs($v1), abs($v2))}]
    set peakF [expr {max($peakF, $g)}]
    set worstU [expr {max($worstU, abs($u1 - $v1), abs($u2 - $v2))}]
    set worstF [expr {max($worstF, abs($f - $g))}]
    if {$g > 0.0 && !$closed} { incr impacts }
    set closed [expr {$g > 0.0}]
  }
  puts "$law, search $search: impacts $impacts, peak force $peakF, peak displacement $peakU, pattern changes $changes, steps redone $redone"
  puts "$law, search $search: largest differences: displacement $worstU, force $worstF"
  check "$law, search $search: the faces pound several times" [expr {$impacts >= 3}] $impacts
  # a sleep and a wake between consecutive impacts (the most damped, jankowski's, may stay within
  # the search distance between two of them)
  check "$law, search $search: the pattern was rebuilt as pairs fell asleep and woke" [expr {$changes >= 2 * ($impacts - 1)}] $changes
  if {$search < 0.005} { check "$law, search $search: steps were redone for sleepers found in contact" [expr {$redone > 0}] $redone }
  check "$law, search $search: same displacements (within 1e-9 of the peak)" [expr {$worstU <= 1e-9 * $peakU}] $worstU
  check "$law, search $search: same contact forces (within 1e-9 of the peak)" [expr {$worstF <= 1e-9 * $peakF}] $worstF
}
}
if {$failures > 0} { exit 1 }
