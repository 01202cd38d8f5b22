# Multiple-support excitation of fixed supports: `pattern MultiSupport` with
# `imposedSupportMotion` on dofs that `fix` also restrains, under the Transformation handler,
# where the imposed motion governs the support. Two supports of a two-mass chain of springs move
# differently: support 1 with an acceleration record (integrated twice), support 4 with a
# displacement history. Writes multisupport-fixed.csv: case, quantity, value (units m, kN, t, s).
# Run: OpenSees multisupport-fixed.tcl (or dabs multisupport-fixed.tcl)
set out [open multisupport-fixed.csv w]
puts $out "case,quantity,value"
proc record {case quantity value} {
  global out
  puts $out [format "%s,%s,%.12e" $case $quantity $value]
}

wipe
model basic -ndm 1 -ndf 1
node 1 0.0; node 2 0.0; node 3 0.0; node 4 0.0
fix 1 1; fix 4 1
mass 2 2.0; mass 3 1.5
uniaxialMaterial Elastic 1 400.0
uniaxialMaterial Elastic 2 250.0
element zeroLength 1 1 2 -mat 1 -dir 1
element zeroLength 2 2 3 -mat 2 -dir 1
element zeroLength 3 3 4 -mat 1 -dir 1

set accel {}
for {set k 0} {$k <= 100} {incr k} {
  set t [expr {0.01*$k}]
  lappend accel [expr {2.0*sin(2*acos(-1)*2.5*$t)*exp(-1.5*$t)}]
}
timeSeries Path 1 -dt 0.01 -values $accel
timeSeries Path 2 -dt 0.1 -values {0.0 0.002 0.006 0.004 -0.002 -0.005 -0.003 0.0 0.001 0.0 0.0}
pattern MultiSupport 1 {
  groundMotion 1 Plain -accel 1
  groundMotion 2 Plain -disp 2
  imposedSupportMotion 1 1 1
  imposedSupportMotion 4 1 2
}
rayleigh 0.2 0.0 0.0 0.0
constraints Transformation
system BandGeneral; numberer Plain; test NormDispIncr 1.0e-12 10; algorithm Newton
integrator Newmark 0.5 0.25; analysis Transient
for {set k 1} {$k <= 80} {incr k} {
  analyze 1 0.01
  if {$k % 4 == 0} {
    foreach n {1 2 3 4} { record step$k u$n [nodeDisp $n 1] }
  }
}
close $out
