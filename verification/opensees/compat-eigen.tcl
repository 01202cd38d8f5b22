# Compatibility input: `eigen` before any analysis command on a model with equalDOF and no
# `constraints` command (OpenSees then builds a transient analysis with the Transformation handler
# and keeps it), `eigen -findLargest n`, an unknown option (warned about and ignored), and a later
# `analyze` that uses the analysis eigen built. A five-node cantilever with a mass tied to its top
# by equalDOF. Blocks: lowest eigenvalues; largest eigenvalues; eigenvalues with an unknown option;
# then time and two displacements under a ground acceleration.
wipe
model basic -ndm 2 -ndf 3
for {set i 1} {$i <= 5} {incr i} { node $i 0.0 [expr {3.0*($i-1)}] }
for {set i 2} {$i <= 5} {incr i} { mass $i [expr {1.0*$i}] 1.0 0.0 }
fix 1 1 1 1
geomTransf Linear 1
for {set i 1} {$i <= 4} {incr i} { element elasticBeamColumn $i $i [expr {$i+1}] 0.1 200000.0 0.001 1 }
node 6 4.0 12.0
fix 6 0 1 1
mass 6 2.0 0.0 0.0
equalDOF 5 6 1
set out [open compat-eigen.out w]
proc row {out values} {
  set text {}
  foreach v $values { lappend text [format %.12g $v] }
  puts $out [join $text " "]
}
puts $out "lowest"
row $out [eigen 3]
puts $out "largest"
row $out [eigen -findLargest 3]
puts $out "unknown option"
row $out [eigen -noSuchSolver 2]
puts $out "time u5 u6"
timeSeries Sine 1 0.0 10.0 0.5 -factor 2.0
pattern UniformExcitation 1 1 -accel 1
for {set i 1} {$i <= 20} {incr i} {
  analyze 1 0.01
  row $out [list [getTime] [nodeDisp 5 1] [nodeDisp 6 1]]
}
close $out
