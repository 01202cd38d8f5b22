# SPDX-License-Identifier: MIT
# Bearing-mass oscillator under the Takatori record: a 500 t deck mass on one
# yoshidaBearing (with back force, hardening and the Maxwell part), the EW record applied at 30
# degrees to global X so both shear directions work at once. Checks that the full Newton
# iteration converges at every step (the consistent tangent) and that the response is a bearing
# response: it yields (peak shear strain above 0.5). Quadratic convergence itself is measured in
# elements/tests/YoshidaBearing3dTest.NewtonConvergesQuadraticallyUnderTakatori.
source [file join [file dirname [info script]] .. lib check.tcl]

set pi [expr {acos(-1.0)}]
set g 9.81
set M 500.0
set Y0 300.0; set U0 0.02; set alpha0 0.2; set gamma 0.01; set k 1000.0; set eta 200.0
wipe
model basic -ndm 3 -ndf 6
node 1 0.0 0.0 0.0
node 2 0.0 0.0 0.0 -mass $M $M $M 0.0 0.0 0.0
fix 1 1 1 1 1 1 1
fix 2 0 0 1 1 1 1
biaxialMaterial Yoshida 1 $Y0 $U0 2.0 $alpha0 0.01 1.2 $gamma -maxwell $k $eta
element yoshidaBearing 1 1 2 1 -Tr 0.2 -Kv 2.0e6 -Kt 500.0 -Kr 8000.0
set record [recordPath RSN1120_KOBE_TAK090.AT2]
set angle [expr {$pi / 6}]
timeSeries Path 1 -filePath $record -dt 0.01 -factor [expr {$g * cos($angle)}]
timeSeries Path 2 -filePath $record -dt 0.01 -factor [expr {$g * sin($angle)}]
pattern UniformExcitation 1 1 -accel 1
pattern UniformExcitation 2 2 -accel 2
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1e-10 10
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set failures 0
set peakStrain 0.0
for {set i 0} {$i < 2000} {incr i} {
  if {[analyze 1 0.01] != 0} { incr failures }
  set peakStrain [expr {max($peakStrain, [lindex [eleResponse 1 shearStrain] 0])}]
}
checkAbs "Newton converged at all 2000 steps (failed steps)" $failures 0 0
checkTrue "bearing yielded: peak shear strain [format %.3f $peakStrain] > 0.5" [expr {$peakStrain > 0.5}]
wipe
finish
