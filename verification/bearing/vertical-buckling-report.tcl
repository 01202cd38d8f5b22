# SPDX-License-Identifier: MIT
# A bearing with the Kumar vertical law (yoshidaBearing -vertical kumar) compressed past its
# critical load at a held shear offset, unloaded, and compressed past it again: the console says
# so once each time it reaches the buckled branch, with the load, the critical load and the
# offset, and analysisStatistics counts it in buckledBearings, as a shear rupture is counted in
# failedBearings.
#
# Closed form of the critical load (Koh and Kelly, with the overlap area of Buckle and Liu 1994,
# as Kumar, Whittaker and Constantinou 2014 use it), computed here from the geometry: a solid
# bearing (no hole, F = 1), S = Do / (4 tr), Ec = 1 / (1/(6 G S^2) + 4/(3 K)), A = pi Do^2 / 4,
# I = pi Do^4 / 64, Tr = n tr, h = Tr + (n - 1) ts, Pe = pi^2 (Ec/3) I h/Tr / h^2,
# Pcr0 = sqrt(Pe G A h/Tr), Pcr(uh) = Pcr0 (d - sin d)/pi with d = 2 acos(uh/Do).
source [file join [file dirname [info script]] .. lib check.tcl]

set G 800.0; set K 2.0e6; set Do 0.8; set ts 0.003; set tr 0.01; set n 20
set offset 0.2
set pi [expr {acos(-1.0)}]
set S [expr {$Do / (4.0 * $tr)}]
set Ec [expr {1.0 / (1.0 / (6.0 * $G * $S * $S) + 4.0 / (3.0 * $K))}]
set A [expr {$pi * $Do * $Do / 4.0}]
set I [expr {$pi * pow($Do, 4) / 64.0}]
set Tr [expr {$n * $tr}]
set h [expr {$Tr + ($n - 1) * $ts}]
set Pe [expr {$pi * $pi * ($Ec / 3.0) * $I * $h / $Tr / ($h * $h)}]
set Pcr0 [expr {sqrt($Pe * $G * $A * $h / $Tr)}]
set d [expr {2.0 * acos($offset / $Do)}]
set Pcr [expr {$Pcr0 * ($d - sin($d)) / $pi}]
set Kv [expr {$Ec * $A / $Tr / (1.0 + 3.0 / ($pi * $pi) * pow($offset / ($Do / 4.0), 2))}]
set uBuckle [expr {-$Pcr / $Kv}]   ;# axial deformation at which the critical load is reached

set script [string map [list @G $G @K $K @Do $Do @ts $ts @tr $tr @n $n @offset $offset \
    @u1 [expr {1.5 * $uBuckle}] @u2 [expr {0.5 * $uBuckle}] @u3 [expr {1.5 * $uBuckle}]] {
  model basic -ndm 3 -ndf 6
  node 1 0.0 0.0 0.0
  node 2 0.0 0.0 0.0
  fix 1 1 1 1 1 1 1
  fix 2 0 1 0 1 1 1
  biaxialMaterial Yoshida 1 150.0 0.012 2.0 0.0 0.0 1.0 0.0
  element yoshidaBearing 1 1 2 1 -vertical kumar @G @K 0.0 @Do @ts @tr @n -limits 99 100
  timeSeries Linear 1
  pattern Plain 1 1 { sp 2 1 @offset }
  constraints Transformation; numberer Plain; system BandGeneral
  test NormDispIncr 1.0e-12 50; algorithm Newton
  integrator LoadControl 0.1; analysis Static
  analyze 10
  loadConst -time 0.0
  timeSeries Linear 2
  pattern Plain 2 2 { load 2 0.0 0.0 1.0 0.0 0.0 0.0 }
  set u 0.0
  foreach target {@u1 @u2 @u3} {
    for {set k 1} {$k <= 40} {incr k} {
      set step [expr {($target - $u) / (41 - $k)}]
      integrator DisplacementControl 2 3 $step
      if {[analyze 1] != 0} { puts "RESULT failed at $u"; exit 1 }
      set u [expr {$u + $step}]
    }
  }
  puts "RESULT [dict get [analysisStatistics] buckledBearings] [dict get [analysisStatistics] failedBearings]"
}]
set f [open buckling.tcl w]; puts $f $script; close $f
set out [exec [info nameofexecutable] buckling.tcl 2>@1]
lassign [lrange [lindex [regexp -all -inline {RESULT [^\n]*} $out] 0] 1 end] buckled failed
set lines [regexp -all -inline {yoshidaBearing 1 buckled at time [^\n]*} $out]
checkTrue "buckledBearings counts the two times the bearing reached the critical load (got $buckled)" \
    [expr {$buckled == 2}]
checkTrue "failedBearings stays 0: no shear rupture (got $failed)" [expr {$failed == 0}]
checkTrue "the console says so once each time (got [llength $lines])" [expr {[llength $lines] == 2}]
foreach line $lines {
  regexp {compression (\S+) reached its critical load (\S+) at a shear offset of (\S+)} $line -> N P u
  check "said critical load = Pcr(uh) of the closed form ([format %.1f $Pcr] kN)" $P $Pcr 1e-5
  check "said shear offset = the held offset" $u $offset 1e-9
  # On the buckled branch the force stays at Pcr, with a stiffness Kv0/1e4 past it.
  checkTrue "said compression at or just past Pcr ($N kN)" [expr {$N >= $Pcr * (1 - 1e-9) && $N <= $Pcr * 1.001}]
}
finish
