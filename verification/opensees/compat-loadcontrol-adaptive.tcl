# Compatibility input: adaptive load control, `integrator LoadControl dLambda Jd minLambda maxLambda`:
# each step's increment is the last one times Jd / (iterations of the last step), kept within the
# bounds. A cantilever column of two force-based elements with Steel01 fiber sections pushed
# laterally past yield under constant axial load. Each row: load factor, tip displacement and the
# iterations of the step (testIter), so a different iteration count shows as a different increment.
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0; node 2 0.0 2.0; node 3 0.0 4.0
fix 1 1 1 1
uniaxialMaterial Steel01 1 350.0 200000.0 0.05
section Fiber 1 {
  patch rect 1 10 1 -0.15 -0.15 0.15 0.15
}
geomTransf PDelta 1
element forceBeamColumn 1 1 2 4 1 1
element forceBeamColumn 2 2 3 4 1 1
timeSeries Constant 1
pattern Plain 1 1 { load 3 0.0 -2.0 0.0 }
system BandGeneral; numberer Plain; constraints Plain; test NormDispIncr 1e-10 30
algorithm Newton; integrator LoadControl 1.0; analysis Static
analyze 1
loadConst -time 0.0
timeSeries Linear 2
pattern Plain 2 2 { load 3 1.0 0.0 0.0 }
integrator LoadControl 0.02 3 0.002 0.05
set out [open compat-loadcontrol-adaptive.out w]
puts $out "lambda ux3 iterations"
for {set i 1} {$i <= 30} {incr i} {
  if {[analyze 1] != 0} break
  puts $out [format "%.10g %.10g %d" [getLoadFactor 2] [nodeDisp 3 1] [testIter]]
}
close $out
