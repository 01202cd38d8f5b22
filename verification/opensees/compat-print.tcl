# Compatibility input: `print` of nodes and elements, to the screen and to a file, in the forms of
# OpenSees' manual (print node/-node tags.., print ele/-ele tags.., print -file name ...).
# A cantilever column (2D, elastic) under a lateral and a vertical load; the node blocks printed to
# a file are read back, and each node's coordinates and displacements written to compat-print.out.
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 0.0 3.5 -mass 2.0 2.0 0.0
node 3 0.0 7.0
fix 1 1 1 1
geomTransf Linear 1
element elasticBeamColumn 1 1 2 0.1 200000.0 0.001 1
element elasticBeamColumn 2 2 3 0.1 200000.0 0.001 1
timeSeries Linear 1
pattern Plain 1 1 { load 3 10.0 -5.0 0.0 }
system BandGeneral; numberer Plain; constraints Plain
integrator LoadControl 0.5; algorithm Linear; analysis Static
analyze 2
print node 3
print ele 1 2
print -node 1
file delete compat-print.txt
print -file compat-print.txt node 2 3
print -file compat-print.txt -node 1
print -file compat-print.txt ele 2

set in [open compat-print.txt]
set out [open compat-print.out w]
puts $out "node-block x y | ux uy rz"
while {[gets $in line] >= 0} {
  if {[regexp {^\s*Coordinates\s*:(.*)$} $line -> numbers]} { set coords $numbers }
  if {[regexp {^\s*Disps:(.*)$} $line -> numbers]} {
    set row {}
    foreach v [concat $coords $numbers] { lappend row [format %.6g $v] }
    puts $out [join $row " "]
  }
}
close $in
close $out
