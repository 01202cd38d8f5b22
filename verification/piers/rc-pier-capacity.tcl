# SPDX-License-Identifier: MIT
# Circular RC pier pushover (2D, one forceBeamColumn with a fiber section: Concrete02 core and
# cover, Steel02 bars, PDelta, axial load 0.1 f'c Ag), pushed by DisplacementControl to 10 % drift,
# well past the peak.
# Checks:
#  1. The base moment at first yield of the extreme tension bar equals a hand section analysis
#     done here in Tcl, independently of dabs: strain compatibility (plane sections) with the
#     concrete integrated over thin horizontal strips of the circle (width 2 sqrt(r^2 - y^2)) and
#     the bars as points, with the published monotonic laws: Kent-Scott-Park parabola and linear
#     descending branch for concrete in compression (Kent & Park 1971, J. Struct. Div. 97(7);
#     Scott, Park & Priestley 1982, ACI J. 79(2)), linear tension softening (Yassin 1994, the
#     Concrete02 tension branch: Ec0 = 2 f'c/eps_c0 up to ft, then slope -Ets), and the
#     Menegotto-Pinto curve for the bars (Menegotto & Pinto 1973; sigma* = b eps* +
#     (1 - b) eps*/(1 + eps*^R0)^(1/R0)). The axial force of the hand section equals -P.
#     The strips and dabs' annular-sector fibers differ, hence a 1.5 % tolerance.
#  2. The run completes to 10 % drift through the softening branch (final shear below 85 % of the
#     peak).
source [file join [file dirname [info script]] .. lib check.tcl]

set kFirstYieldTol 0.015

set PI [expr {acos(-1.0)}]
set D 1.5; set cover 0.05; set L 8.0
set R [expr {$D / 2.0}]; set rc [expr {$R - $cover}]
set nBars 24; set barA 0.000804; set rb [expr {$rc - 0.016}]
# Concrete02: fc epsc0 fcu epscu lambda ft Ets (kN, m)
set core  {-35000.0 -0.0025 -7000.0 -0.02 0.1 2800.0 1.4e6}
set cov   {-30000.0 -0.002 -6000.0 -0.005 0.1 2500.0 1.2e6}
set fy 420000.0; set Es 2.0e8; set bh 0.01; set R0 18.0
set epsY [expr {$fy / $Es}]
set P [expr {0.1 * 30000.0 * $PI * $D * $D / 4.0}]

# ------------------------------------------------------------------ hand section analysis
proc concreteStress {eps props} {
  lassign $props fc e0 fcu ecu lam ft ets
  if {$eps < 0.0} {
    if {$eps >= $e0} { set eta [expr {$eps / $e0}]; return [expr {$fc * (2.0 * $eta - $eta * $eta)}] }
    if {$eps >= $ecu} { return [expr {$fc + ($fcu - $fc) * ($eps - $e0) / ($ecu - $e0)}] }
    return $fcu
  }
  set ec0 [expr {2.0 * $fc / $e0}]
  if {$eps <= $ft / $ec0} { return [expr {$ec0 * $eps}] }
  return [expr {max(0.0, $ft - $ets * ($eps - $ft / $ec0))}]
}
proc steelStress {eps} {
  global fy bh R0 epsY
  set x [expr {$eps / $epsY}]
  return [expr {$fy * ($bh * $x + (1.0 - $bh) * $x / pow(1.0 + pow(abs($x), $R0), 1.0 / $R0))}]
}
# Resultants [N, M] for strain eps(y) = eps0 + phi y (tension at +y; M = -sum(sigma y A), so
# that M > 0 for phi > 0 in dabs' sign convention with y -> -y).
proc sectionForces {eps0 phi} {
  global R rc rb nBars barA core cov PI
  set n 1500
  set dy [expr {2.0 * $R / $n}]
  set N 0.0; set M 0.0
  for {set i 0} {$i < $n} {incr i} {
    set y [expr {-$R + ($i + 0.5) * $dy}]
    set wAll [expr {2.0 * sqrt(max(0.0, $R * $R - $y * $y))}]
    set wCore [expr {2.0 * sqrt(max(0.0, $rc * $rc - $y * $y))}]
    set eps [expr {$eps0 + $phi * $y}]
    set f [expr {([concreteStress $eps $core] * $wCore + [concreteStress $eps $cov] * ($wAll - $wCore)) * $dy}]
    set N [expr {$N + $f}]; set M [expr {$M + $f * $y}]
  }
  for {set k 0} {$k < $nBars} {incr k} {
    set y [expr {$rb * cos(2.0 * $PI * $k / $nBars)}]
    set f [expr {[steelStress [expr {$eps0 + $phi * $y}]] * $barA}]
    set N [expr {$N + $f}]; set M [expr {$M + $f * $y}]
  }
  return [list $N $M]
}
# First yield: extreme bar (y = rb) at eps_y; find phi with N = -P by bisection (N falls with phi).
set lo 0.0; set hi [expr {20.0 * $epsY / $rb}]
for {set it 0} {$it < 60} {incr it} {
  set phi [expr {0.5 * ($lo + $hi)}]
  lassign [sectionForces [expr {$epsY - $phi * $rb}] $phi] N M
  if {$N > -$P} { set lo $phi } else { set hi $phi }
}
set phiYHand $phi
set MyHand [expr {abs($M)}]
puts [format "hand section analysis: first yield at phi = %.5e 1/m, M = %.1f kN m (N = %.1f, -P = %.1f)" $phiYHand $MyHand $N [expr {-$P}]]

# ------------------------------------------------------------------ dabs model
wipe
model basic -ndm 2 -ndf 3
uniaxialMaterial Concrete02 1 {*}$core
uniaxialMaterial Concrete02 2 {*}$cov
uniaxialMaterial Steel02 3 $fy $Es $bh $R0 0.925 0.15
section Fiber 1 {
  patch circ 1 24 10 0.0 0.0 0.0 $rc 0.0 360.0
  patch circ 2 24 2 0.0 0.0 $rc $R 0.0 360.0
  layer circ 3 $nBars $barA 0.0 0.0 $rb 0.0 [expr {360.0 - 360.0 / $nBars}]
}
beamIntegration Lobatto 1 1 5
geomTransf PDelta 1
node 1 0.0 0.0; node 2 0.0 $L
fix 1 1 1 1
element forceBeamColumn 1 1 2 1 1
timeSeries Constant 1
pattern Plain 1 1 { load 2 0.0 [expr {-$P}] 0.0 }
constraints Plain; numberer Plain; system BandGeneral
test NormDispIncr 1e-8 50; algorithm Newton
integrator LoadControl 0.1; analysis Static
checkTrue "axial load applied" [expr {[analyze 10] == 0}]
loadConst -time 0.0
timeSeries Linear 2
pattern Plain 2 2 { load 2 1.0 0.0 0.0 }

# The tension side of the base section: pushing in +X bends about z with local y = -X, so the
# tension face is at local y = +rb or -rb; track the larger bar strain of the two extreme bars.
proc barStrain {} {
  global rb
  set a [lindex [eleResponse 1 section 1 fiber $rb 0.0 3 stressStrain] 1]
  set b [lindex [eleResponse 1 section 1 fiber [expr {-$rb}] 0.0 3 stressStrain] 1]
  return [expr {max($a, $b)}]
}
set du 0.0005
integrator DisplacementControl 2 1 $du
set prev [list 0.0 0.0]
set MyDabs {}
set peakV 0.0; set V 0.0
set target [expr {0.10 * $L}]
set completed 1
while {[nodeDisp 2 1] < $target - 1e-12} {
  if {[analyze 1] != 0} {
    test NormDispIncr 1e-8 200
    integrator DisplacementControl 2 1 [expr {$du / 10.0}]
    set bad 0
    for {set k 0} {$k < 10 && !$bad} {incr k} { set bad [expr {[analyze 1] != 0}] }
    test NormDispIncr 1e-8 50
    integrator DisplacementControl 2 1 $du
    if {$bad} { set completed 0; break }
  }
  reactions
  set M [expr {abs([nodeReaction 1 3])}]
  set V [expr {-[nodeReaction 1 1]}]
  set peakV [expr {max($peakV, $V)}]
  set e [barStrain]
  if {$MyDabs eq "" && $e >= $epsY} {
    lassign $prev e0 m0
    set MyDabs [expr {$m0 + ($M - $m0) * ($epsY - $e0) / ($e - $e0)}]
    puts [format "dabs: first yield of the extreme bar at tip drift %.4f m, base moment %.1f kN m" [nodeDisp 2 1] $MyDabs]
  }
  set prev [list $e $M]
  # coarser steps after yield
  if {$MyDabs ne "" && $du < 0.004} { set du 0.004; integrator DisplacementControl 2 1 $du }
}
puts [format "pushover ended at u = %.3f m (drift %.1f %%), shear %.1f kN, peak %.1f kN" \
    [nodeDisp 2 1] [expr {100.0 * [nodeDisp 2 1] / $L}] $V $peakV]
checkTrue "the extreme bar yields during the pushover" [expr {$MyDabs ne ""}]
if {$MyDabs ne ""} {
  check "base moment at first yield of the extreme bar = hand section analysis" $MyDabs $MyHand $kFirstYieldTol
}
checkTrue "DisplacementControl pushover completes to 10 % drift" [expr {$completed && [nodeDisp 2 1] >= $target - 1e-9}]
checkTrue "the run went through softening: final shear < 85 % of the peak" [expr {$V < 0.85 * $peakV}]
finish
