# SPDX-License-Identifier: MIT
# Fits the Mavroeidis-Papageorgiou (2003) near-fault pulse to the Takatori EW record, so
# that the bridge case study has a built-in motion when the record is not shipped.
#
#   dabs verification/bridge/tools/fit-pulse.tcl ?record.AT2?
#
# Method: the record's acceleration (g) is integrated to ground velocity by the trapezoid rule
# (the PEER .AT2 values after the 4-line header) and a linear trend fitted to
# the whole velocity record is removed (baseline correction). The pulse velocity
#   v(t) = Vp/2 [1 + cos(2 pi (t - t0)/(gamma Tp))] cos(2 pi (t - t0)/Tp + nu),  |t - t0| <= gamma Tp/2
# is fitted by least squares on velocity over 0 .. 20 s (sampled every 0.02 s): Vp enters
# linearly and is solved for exactly; (Tp, gamma, nu, t0) by Nelder-Mead from the best point of a
# coarse grid. Prints the parameters (copied into bridge.tcl, pulseTp ... pulseT0), the fit's
# relative rms error and the peak ground velocities, and checks that `timeSeries NearFaultPulse
# -velocity` reproduces the formula.
set pi [expr {acos(-1.0)}]
set g 9.81
set here [file dirname [info script]]
set record [expr {$argc > 0 ? [lindex $argv 0] :
    [file normalize [file join $here .. .. data RSN1120_KOBE_TAK090.AT2]]}]

set fh [open $record r]
for {set i 0} {$i < 3} {incr i} { gets $fh }
gets $fh header
regexp {DT=\s*([0-9.Ee+-]+)} $header -> dtRec
set acc [string trim [read $fh]]
close $fh
# Velocity on the record's own step by the trapezoid rule (the record starts at t = dt;
# a zero value at t = 0 is prepended, as `timeSeries Path` does not but a record at rest implies).
set v 0.0; set a0 0.0
set ts {}; set vs {}
set i 0
foreach aval $acc {
  incr i
  set t [expr {$i * $dtRec}]
  if {$t > 20.0 + 1e-9} break
  set a1 [expr {$aval * $g}]
  set v [expr {$v + 0.5 * $dtRec * ($a0 + $a1)}]
  set a0 $a1
  if {$i % 2 == 0} { lappend ts $t; lappend vs $v }
}
# baseline: remove the least-squares line
set n [llength $ts]; set st 0.0; set sv 0.0; set stt 0.0; set stv 0.0
foreach t $ts vv $vs { set st [expr {$st + $t}]; set sv [expr {$sv + $vv}]; set stt [expr {$stt + $t*$t}]; set stv [expr {$stv + $t*$vv}] }
set slope [expr {($n * $stv - $st * $sv) / ($n * $stt - $st * $st)}]
set icpt [expr {($sv - $slope * $st) / $n}]
set vobs {}
foreach t $ts vv $vs { lappend vobs [expr {$vv - $icpt - $slope * $t}] }
set vNorm 0.0; set pgv 0.0
foreach vv $vobs { set vNorm [expr {$vNorm + $vv * $vv}]; set pgv [expr {max($pgv, abs($vv))}] }

proc shape {t Tp gamma nu t0} {
  set x [expr {$t - $t0}]
  if {abs($x) > 0.5 * $gamma * $Tp} { return 0.0 }
  return [expr {0.5 * (1.0 + cos(2.0 * $::pi * $x / ($gamma * $Tp))) * cos(2.0 * $::pi * $x / $Tp + $nu)}]
}
# Residual sum of squares with the optimal Vp; returns {rss Vp}.
proc cost {p} {
  lassign $p Tp gamma nu t0
  if {$Tp <= 0.2 || $gamma <= 1.01 || $gamma > 5.0 || $t0 < 0.5 * $gamma * $Tp} { return {1e30 0} }
  set sff 0.0; set sfv 0.0
  foreach t $::ts vv $::vobs {
    set f [shape $t $Tp $gamma $nu $t0]
    set sff [expr {$sff + $f * $f}]; set sfv [expr {$sfv + $f * $vv}]
  }
  if {$sff == 0.0} { return {1e30 0} }
  set Vp [expr {$sfv / $sff}]
  return [list [expr {$::vNorm - $sfv * $sfv / $sff}] $Vp]
}
# coarse grid
set best {1e30}
foreach Tp {0.8 1.0 1.2 1.4 1.6 2.0} {
  foreach gamma {1.5 2.0 2.5 3.0} {
    foreach nu {0.0 1.57 3.14 4.71} {
      for {set t0 2.0} {$t0 <= 10.0} {set t0 [expr {$t0 + 0.5}]} {
        set c [lindex [cost [list $Tp $gamma $nu $t0]] 0]
        if {$c < [lindex $best 0]} { set best [list $c $Tp $gamma $nu $t0] }
      }
    }
  }
}
# Nelder-Mead
proc nelderMead {x0 steps iters} {
  set simplex [list [list [lindex [cost $x0] 0] $x0]]
  for {set i 0} {$i < [llength $x0]} {incr i} {
    set x $x0; lset x $i [expr {[lindex $x $i] + [lindex $steps $i]}]
    lappend simplex [list [lindex [cost $x] 0] $x]
  }
  set d [llength $x0]
  for {set it 0} {$it < $iters} {incr it} {
    set simplex [lsort -real -index 0 $simplex]
    set worst [lindex $simplex end 1]; set fw [lindex $simplex end 0]
    set c {}
    for {set i 0} {$i < $d} {incr i} {
      set s 0.0
      for {set k 0} {$k < $d} {incr k} { set s [expr {$s + [lindex $simplex $k 1 $i]}] }
      lappend c [expr {$s / $d}]
    }
    proc along {c w f} { set r {}; foreach ci $c wi $w { lappend r [expr {$ci + $f * ($wi - $ci)}] }; return $r }
    set xr [along $c $worst -1.0]; set fr [lindex [cost $xr] 0]
    if {$fr < [lindex $simplex 0 0]} {
      set xe [along $c $worst -2.0]; set fe [lindex [cost $xe] 0]
      lset simplex end [expr {$fe < $fr ? [list $fe $xe] : [list $fr $xr]}]
    } elseif {$fr < [lindex $simplex end-1 0]} {
      lset simplex end [list $fr $xr]
    } else {
      set xc [along $c $worst 0.5]; set fc [lindex [cost $xc] 0]
      if {$fc < $fw} { lset simplex end [list $fc $xc] } else {
        set xb [lindex $simplex 0 1]
        for {set k 1} {$k <= $d} {incr k} {
          set xk [along $xb [lindex $simplex $k 1] 0.5]
          lset simplex $k [list [lindex [cost $xk] 0] $xk]
        }
      }
    }
  }
  return [lindex [lsort -real -index 0 $simplex] 0]
}
set sol [nelderMead [lrange $best 1 end] {0.1 0.3 0.5 0.3} 300]
lassign [lindex $sol 1] Tp gamma nu t0
lassign [cost [lindex $sol 1]] rss Vp
if {$Vp < 0} { set Vp [expr {-$Vp}]; set nu [expr {$nu + $pi}] }
set nu [expr {fmod($nu, 2.0 * $pi)}]; if {$nu < 0} { set nu [expr {$nu + 2.0 * $pi}] }
puts [format "fitted: -Tp %.3f -Vp %.3f -gamma %.3f -nu %.3f -t0 %.3f" $Tp $Vp $gamma $nu $t0]
puts [format "relative rms error on velocity (0-20 s): %.3f; record PGV %.3f m/s" [expr {sqrt($rss / $vNorm)}] $pgv]
# The program's series reproduces the formula: a unit spring loaded by the series (-velocity)
# under load control with the pseudo-time advancing 0.02 s per step has u(t) = v(t).
wipe
model basic -ndm 1 -ndf 1
node 1 0.0; node 2 0.0
fix 1 1
uniaxialMaterial Elastic 1 1.0
element zeroLength 1 1 2 -mat 1 -dir 1
timeSeries NearFaultPulse 2 -Tp $Tp -Vp $Vp -gamma $gamma -nu $nu -t0 $t0 -velocity
pattern Plain 1 2 { load 2 1.0 }
constraints Plain; numberer Plain; system FullGeneral; test NormDispIncr 1e-12 5
algorithm Linear; integrator LoadControl 0.02; analysis Static
set worst 0.0; set pulsePgv 0.0
foreach t $ts {
  analyze 1
  set f [expr {$Vp * [shape [getTime %.17g] $Tp $gamma $nu $t0]}]
  set worst [expr {max($worst, abs([nodeDisp 2 1] - $f))}]
  set pulsePgv [expr {max($pulsePgv, abs($f))}]
}
puts [format "pulse PGV %.3f m/s; largest difference formula vs timeSeries NearFaultPulse: %.2e m/s" $pulsePgv $worst]
set f [open pulse-fit.csv w]
puts $f "t,record_velocity,pulse_velocity"
foreach t $ts vv $vobs { puts $f "$t,$vv,[expr {$Vp * [shape $t $Tp $gamma $nu $t0]}]" }
close $f
