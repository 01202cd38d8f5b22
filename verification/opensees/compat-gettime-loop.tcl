# Compatibility input: `getTime` in `while {[getTime] < $tEnd}` loops. OpenSees returns the time
# formatted with %f, so a loop of steps that sum to tEnd with round-off stops at tEnd. Each row:
# the steps taken and the last time returned, for transient steps of 0.01 and 0.1 up to 1 and
# for static load steps of 0.1 up to 1; then getTime with a format of the script's own.
wipe
model basic -ndm 1 -ndf 1
node 1 0.0; node 2 1.0 -mass 1.0
fix 1 1
uniaxialMaterial Elastic 1 100.0
element truss 1 1 2 1.0 1
timeSeries Linear 1
pattern Plain 1 1 { load 2 1.0 }
system BandGeneral; numberer Plain; constraints Plain; test NormDispIncr 1e-12 10
algorithm Newton
set out [open compat-gettime-loop.out w]
puts $out "steps time"
foreach dt {0.01 0.1} {
  integrator Newmark 0.5 0.25; analysis Transient
  setTime 0.0
  set n 0
  while {[getTime] < 1.0} { analyze 1 $dt; incr n }
  puts $out "$n [getTime]"
}
wipeAnalysis
system BandGeneral; numberer Plain; constraints Plain; test NormDispIncr 1e-12 10
algorithm Newton; integrator LoadControl 0.1; analysis Static
setTime 0.0
set n 0
while {[getTime] < 1.0} { analyze 1; incr n }
puts $out "$n [getTime]"
puts $out "$n [getTime %.3f]"
close $out
