# SPDX-License-Identifier: MIT
# A spring and a mass under a sine load, 2000 steps: `analyze` with the option given as argv.
model basic -ndm 1 -ndf 1
node 1 0.0; node 2 1.0; fix 1 1; mass 2 1.0
uniaxialMaterial Elastic 1 100.0
element zeroLength 1 1 2 -mat 1 -dir 1
timeSeries Sine 1 0.0 100.0 1.0
pattern Plain 1 1 { load 2 1.0 }
constraints Plain; numberer Plain; system BandGeneral; test NormDispIncr 1e-10 10
algorithm Newton; integrator Newmark 0.5 0.25; analysis Transient
puts [analyze 2000 0.001 {*}$argv]
