# Compatibility input: `integrator TRBDF2` (Bathe's composite scheme: steps alternate between the
# trapezoidal rule and the three-point backward difference) on a damped SDOF under a sine load,
# first with steps of 0.02 s, then of 0.01 s (a new step size restarts the alternation). Each row:
# time, displacement, velocity, acceleration.
wipe
model basic -ndm 1 -ndf 1
node 1 0.0
node 2 0.0 -mass 2.0
fix 1 1
uniaxialMaterial Elastic 1 800.0
element zeroLength 1 1 2 -mat 1 -dir 1
timeSeries Sine 1 0.0 100.0 0.25 -factor 10.0
pattern Plain 1 1 { load 2 1.0 }
rayleigh 0.4 0.0 0.0 0.0
system BandGeneral; numberer Plain; constraints Plain; test NormDispIncr 1e-12 10
algorithm Newton; integrator TRBDF2; analysis Transient
set out [open compat-trbdf2.out w]
puts $out "time u v a"
foreach {n dt} {40 0.02 40 0.01} {
  for {set i 1} {$i <= $n} {incr i} {
    analyze 1 $dt
    puts $out [format "%.10g %.10g %.10g %.10g" [getTime] [nodeDisp 2 1] [nodeVel 2 1] [nodeAccel 2 1]]
  }
}
close $out
