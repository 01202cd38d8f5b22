# Compatibility input: Node recorder options `-load` (OpenSees' synonym of -time), `-closeOnWrite`,
# and `-timeSeries` with one series per dof (absolute accelerations) and with fewer series than dofs
# (OpenSees warns and ignores the option). A cantilever with a tip mass: a static push recorded
# with -load, then free vibration under a ground acceleration. The recorder files are read back
# after `wipe` closed them; each block is one file.
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 0.0 3.0 -mass 5.0 5.0 0.0
fix 1 1 1 1
geomTransf Linear 1
element elasticBeamColumn 1 1 2 0.05 30000.0 0.0004 1
timeSeries Linear 1
pattern Plain 1 1 { load 2 2.0 -1.0 0.0 }
recorder Node -file compat-rec-load.txt -load -node 2 -dof 1 2 disp
system BandGeneral; numberer Plain; constraints Plain; test NormDispIncr 1e-12 10
algorithm Newton; integrator LoadControl 0.25; analysis Static
analyze 4
remove recorders
loadConst -time 0.0
wipeAnalysis
timeSeries Sine 2 0.0 10.0 0.3 -factor 2.0
pattern UniformExcitation 2 1 -accel 2
recorder Node -file compat-rec-close.txt -time -closeOnWrite -node 2 -dof 1 3 disp
recorder Node -file compat-rec-abs.txt -time -timeSeries 2 0 0 -node 2 -dof 1 2 3 accel
recorder Node -file compat-rec-fewer.txt -time -timeSeries 2 -node 2 -dof 1 2 3 accel
system BandGeneral; numberer Plain; constraints Plain; test NormDispIncr 1e-12 10
algorithm Newton; integrator Newmark 0.5 0.25; analysis Transient
analyze 20 0.01
wipe
set out [open compat-recorders.out w]
foreach name {load close abs fewer} {
  puts $out "file compat-rec-$name.txt"
  set in [open compat-rec-$name.txt]
  puts -nonewline $out [read $in]
  close $in
}
close $out
