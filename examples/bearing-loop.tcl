# SPDX-License-Identifier: MIT
# One high-damping rubber bearing (Yoshida model) sheared in cycles at 50, 100 and 200 % strain and
# along a circle (units kN, m, s, t). Prints Keq, Geq and the damping ratio heq per amplitude and
# the energy of one circular orbit; writes the loops to bearing-loop.txt (and bearing-loop.png).
set A 1.6; set Tr 0.2; set pi [expr {acos(-1.0)}]   ;# rubber area (m^2) and thickness (m)
# HDR set (a) of verification/bearing/fitted-parameters.md, per unit area and unit thickness:
# Y0 (MPa) U0 (strain) n alpha0 beta q gamma. Scale: force Y0*A (kN), displacement U0*Tr (m).
lassign {0.435794 0.0683367 0.115167 0.831926 0.698464 0.0393774 0.000947439} y0 u0 n a0 b q g
# Builds a fresh bearing, imposes the path {{x y} ..} on its top node, returns {{x y Fx Fy} ..}
proc drive {path} {
  global A Tr y0 u0 n a0 b q g
  wipe; model basic -ndm 3 -ndf 6
  node 1 0 0 0; node 2 0 0 0               ;# bottom and top of the bearing (zero length)
  fix 1 1 1 1 1 1 1; fix 2 0 0 0 1 1 1     ;# top: shear X, Y imposed below, vertical free
  biaxialMaterial Yoshida 1 [expr {$y0*1000*$A}] [expr {$u0*$Tr}] $n $a0 $b $q $g
  element yoshidaBearing 1 1 2 1 -Tr $Tr -Kv 1.0e6   ;# local y = global X, local z = global Y
  # Imposed displacements: one Path series per direction, one value per pseudo-time step
  timeSeries Path 1 -dt 1 -values [concat 0 [lmap p $path {lindex $p 0}]] -useLast
  timeSeries Path 2 -dt 1 -values [concat 0 [lmap p $path {lindex $p 1}]] -useLast
  pattern Plain 1 1 { sp 2 1 1.0 }; pattern Plain 2 2 { sp 2 2 1.0 }
  constraints Transformation; numberer Plain; system BandGeneral
  test NormDispIncr 1e-10 20; algorithm Newton; integrator LoadControl 1.0; analysis Static
  set out {}; foreach p $path {
    if {[analyze 1] != 0} { puts "FAILED: analysis of the bearing"; exit 1 }
    set f [eleResponse 1 basicForce]       ;# {axial, shear y, shear z, ...}
    lappend out [list [nodeDisp 2 1] [nodeDisp 2 2] [lindex $f 1] [lindex $f 2]]
  }; return $out
}
proc work {rows} {   ;# work of the force along a path (trapezoid rule): a closed loop's dissipated energy
  set w 0.0; foreach r0 [lrange $rows 0 end-1] r1 [lrange $rows 1 end] {
    lassign $r0 x0 y0 fx0 fy0; lassign $r1 x1 y1 fx1 fy1
    set w [expr {$w + 0.5*(($fx0 + $fx1)*($x1 - $x0) + ($fy0 + $fy1)*($y1 - $y0))}]
  }; return $w
}
set txt [open bearing-loop.txt w]; puts "strain   Keq (kN/m)  Geq (MPa)  heq     dW (kN m)  (fitted-parameters.md: Geq, heq)"
# Each amplitude with the Geq (MPa) and heq of the same set and protocol in fitted-parameters.md
foreach {strain G h} {0.5 0.8898 0.2303 1.0 0.6642 0.2138 2.0 0.5810 0.1771} {
  set X [expr {$strain*$Tr}]; set path {}
  # The calibration's protocol: a quarter cycle to +X, 12 half cycles, 40 steps a quarter
  for {set i 1} {$i <= 1000} {incr i} { lappend path [list [expr {$X*asin(sin($pi*$i/80.0))*2/$pi}] 0] }
  set rows [lrange [drive $path] end-160 end]   ;# the last full cycle (+X to -X to +X)
  set Keq [expr {([lindex $rows 0 2] - [lindex $rows 80 2])/(2*$X)}]  ;# (F+ - F-)/2X
  set dW [work $rows]; set heq [expr {$dW/(2*$pi*$Keq*$X*$X)}]   ;# loop area, damping ratio
  set Geq [expr {$Keq*$Tr/$A/1000}]; set dW$strain $dW              ;# shear modulus (MPa)
  puts [format "%4.0f %%   %9.1f   %7.4f   %6.4f  %8.2f   (%s)" [expr {$strain*100}] $Keq $Geq $heq $dW "$G $h"]
  foreach r $rows { puts $txt "[lindex $r 0] [lindex $r 2]" }; puts $txt "\n"
  if {$dW <= 0 || abs($Geq - $G) > 0.01*$G || abs($heq - $h) > 0.01*$h} { puts "FAILED: loop at $strain off the table"; exit 1 }
}
# Circular orbit of radius 100 % strain: ramp out along X, then three revolutions (last measured)
set R $Tr; set path {}; for {set i 1} {$i <= 40} {incr i} { lappend path [list [expr {$R*$i/40.0}] 0] }
for {set i 1} {$i <= 480} {incr i} { lappend path [list [expr {$R*cos($pi*$i/80)}] [expr {$R*sin($pi*$i/80)}]] }
set rows [lrange [drive $path] end-160 end]; set dW [work $rows]
puts [format "orbit at 100 %%: dW per revolution %.2f kN m (%.2f times a 100 %% cycle along X), |F| %.1f kN" \
    $dW [expr {$dW/${dW1.0}}] [expr {hypot([lindex $rows end 2], [lindex $rows end 3])}]]
foreach r $rows { puts $txt "[lindex $r 0] [lindex $r 2] [lindex $r 1] [lindex $r 3]" }; close $txt
if {$dW <= 0} { puts "FAILED: the orbit dissipated no energy"; exit 1 }
# A picture of the loops with gnuplot, when it is installed (the text file is the result)
catch {exec gnuplot -e "set terminal png size 800,500; set output 'bearing-loop.png'; set xlabel 'displacement X (m)'; set ylabel 'shear X (kN)';\
  plot 'bearing-loop.txt' index 0:2 using 1:2 with lines title 'cycles at 50, 100, 200 %', '' index 3 using 1:2 with lines title 'orbit at 100 %, X part'"}
