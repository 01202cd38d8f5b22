# Compatibility input: `initialize` (no arguments) between setting up a transient analysis and
# running it, as OpenSees' examples do before the first `analyze`. A 2D portal frame with masses
# under a sine ground acceleration; each row: time and the roof displacements.
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0; node 2 6.0 0.0
node 3 0.0 4.0 -mass 10.0 10.0 0.0
node 4 6.0 4.0 -mass 10.0 10.0 0.0
fix 1 1 1 1; fix 2 1 1 1
geomTransf Linear 1
element elasticBeamColumn 1 1 3 0.09 25000.0 0.000675 1
element elasticBeamColumn 2 2 4 0.09 25000.0 0.000675 1
element elasticBeamColumn 3 3 4 0.12 25000.0 0.0016 1
timeSeries Sine 1 0.0 2.0 0.4 -factor 3.0
pattern UniformExcitation 1 1 -accel 1
rayleigh 0.2 0.0 0.0 0.002
system BandGeneral; numberer RCM; constraints Plain; test NormDispIncr 1e-12 10
algorithm Newton; integrator Newmark 0.5 0.25; analysis Transient
initialize
set out [open compat-initialize.out w]
puts $out "time ux3 uy3 rz3 ux4"
for {set i 1} {$i <= 100} {incr i} {
  analyze 1 0.01
  puts $out [format "%.10g %.10g %.10g %.10g %.10g" [getTime] [nodeDisp 3 1] [nodeDisp 3 2] [nodeDisp 3 3] [nodeDisp 4 1]]
}
close $out
