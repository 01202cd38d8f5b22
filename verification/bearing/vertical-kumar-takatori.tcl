# SPDX-License-Identifier: MIT
# A 500 t deck mass on one yoshidaBearing with the Kumar vertical law and P-Delta moments
# (-vertical kumar ... -pDelta): the dead load first (static), then the Takatori EW record at 30
# degrees to global X. Checks: the settlement under the dead load is W/Kv0 with Kv0 = Ec A/Tr
# computed here from the bearing's dimensions (Kumar et al. 2014); the full Newton iteration with
# the non-symmetric tangent (dN/dU, P-Delta) converges at every step; at the step of the largest
# shear displacement the element's Kv equals Kv0/(1 + 3/pi^2 (uh/r)^2) at that displacement.
source [file join [file dirname [info script]] .. lib check.tcl]

set pi [expr {acos(-1.0)}]
set g 9.81
set M 500.0
# Rubber and geometry (kN, m): the bearing of verification/opensees/elastomericx-vertical.tcl.
set G 800.0; set K 2.0e6; set Di 0.1; set Do 0.8; set ts 0.003; set tr 0.01; set n 20

# Kv0 and r by hand (Kumar et al. 2014; the shape factor of an annulus, F for the hole).
set A [expr {$pi / 4.0 * ($Do * $Do - $Di * $Di)}]
set r [expr {sqrt($Do * $Do + $Di * $Di) / 4.0}]
set S [expr {($Do - $Di) / (4.0 * $tr)}]
set a [expr {$Do / $Di}]
set F [expr {($a * $a + 1.0) / (($a - 1.0) ** 2) + (1.0 + $a) / ((1.0 - $a) * log($a))}]
set Ec [expr {1.0 / (1.0 / (6.0 * $G * $S * $S * $F) + 4.0 / (3.0 * $K))}]
set Kv0 [expr {$Ec * $A / ($n * $tr)}]

wipe
model basic -ndm 3 -ndf 6
node 1 0.0 0.0 0.0
node 2 0.0 0.0 0.0 -mass $M $M $M 0.0 0.0 0.0
fix 1 1 1 1 1 1 1
fix 2 0 0 0 1 1 1
biaxialMaterial Yoshida 1 300.0 0.02 2.0 0.2 0.01 1.2 0.01 -maxwell 1000.0 200.0
element yoshidaBearing 1 1 2 1 -vertical kumar $G $K $Di $Do $ts $tr $n -Kt 500.0 \
  -Kr 8000.0 -pDelta
set W [expr {$M * $g}]
timeSeries Constant 10
pattern Plain 10 10 {
  load 2 0.0 0.0 [expr {-$W}] 0.0 0.0 0.0
}
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1e-10 10
algorithm Newton
integrator LoadControl 1.0
analysis Static
checkAbs "dead load converged" [analyze 1] 0 0
check "settlement under the dead load = W/Kv0" [nodeDisp 2 3] [expr {-$W / $Kv0}] 1e-9
loadConst -time 0.0
wipeAnalysis

set record [recordPath RSN1120_KOBE_TAK090.AT2]
set angle [expr {$pi / 6}]
timeSeries Path 1 -filePath $record -dt 0.01 -factor [expr {$g * cos($angle)}]
timeSeries Path 2 -filePath $record -dt 0.01 -factor [expr {$g * sin($angle)}]
pattern UniformExcitation 1 1 -accel 1
pattern UniformExcitation 2 2 -accel 2
constraints Plain
numberer Plain
system UmfPack
test NormDispIncr 1e-10 10
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set failures 0
set peakUh 0.0
set kvAtPeak 0.0
for {set i 0} {$i < 2000} {incr i} {
  if {[analyze 1 0.01] != 0} { incr failures }
  set d [eleResponse 1 basicDeformation]
  set uh [expr {hypot([lindex $d 1], [lindex $d 2])}]
  if {$uh > $peakUh} {
    set peakUh $uh
    set kvAtPeak [lindex [eleResponse 1 verticalStiffness] 0]
  }
}
checkAbs "Newton converged at all 2000 steps (failed steps)" $failures 0 0
checkTrue "the bearing sheared well past yield: peak |U| [format %.3f $peakUh] m > 0.1 m" \
  [expr {$peakUh > 0.1}]
check "Kv at the largest shear = Kv0 / (1 + 3/pi^2 (uh/r)^2)" $kvAtPeak \
  [expr {$Kv0 / (1.0 + 3.0 / ($pi * $pi) * ($peakUh / $r) ** 2)}] 1e-9
wipe
finish
