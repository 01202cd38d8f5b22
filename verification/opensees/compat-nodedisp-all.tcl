# Compatibility input: `nodeDisp node 0` (and nodeVel/nodeAccel with a dof below 1) return the
# whole vector, as `nodeDisp node` does. A 2D cantilever with a mass at its tip, in free vibration
# after an initial static push; each row: step, then nodeDisp/nodeVel/nodeAccel of the tip with
# dof 0, dof -1 and no dof.
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 0.0 3.0 -mass 5.0 5.0 0.0
fix 1 1 1 1
geomTransf Linear 1
element elasticBeamColumn 1 1 2 0.05 30000.0 0.0004 1
timeSeries Linear 1
pattern Plain 1 1 { load 2 2.0 0.0 0.0 }
system BandGeneral; numberer Plain; constraints Plain; test NormDispIncr 1e-12 10
algorithm Newton; integrator LoadControl 1.0; analysis Static
analyze 1
loadConst -time 0.0
remove loadPattern 1
wipeAnalysis
system BandGeneral; numberer Plain; constraints Plain; test NormDispIncr 1e-12 10
algorithm Newton; integrator Newmark 0.5 0.25; analysis Transient
set out [open compat-nodedisp-all.out w]
puts $out "step | disp(0) disp(-1) disp | vel(0) vel | accel(0) accel"
for {set i 1} {$i <= 10} {incr i} {
  analyze 1 0.005
  set row [concat $i [nodeDisp 2 0] [nodeDisp 2 -1] [nodeDisp 2] [nodeVel 2 0] [nodeVel 2] [nodeAccel 2 0] [nodeAccel 2]]
  set text {}
  foreach v $row { lappend text [format %.10g $v] }
  puts $out [join $text " "]
}
close $out
