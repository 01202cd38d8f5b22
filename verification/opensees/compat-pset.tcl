# Compatibility input: `pset name value` sets a Tcl variable (and returns it); `pset name` reads
# it. Parameters of an elastic truss set with pset; each row: the values pset returned and read,
# and the tip displacement under load.
wipe
pset E 29000.0
set A [pset A 5.0]
pset L 144.0
model basic -ndm 2 -ndf 2
node 1 0.0 0.0
node 2 $L 0.0
fix 1 1 1
fix 2 0 1
uniaxialMaterial Elastic 1 [pset E]
element truss 1 1 2 $A 1
timeSeries Linear 1
pattern Plain 1 1 { load 2 100.0 0.0 }
system BandGeneral; numberer Plain; constraints Plain; integrator LoadControl 1.0
algorithm Linear; analysis Static
analyze 1
set out [open compat-pset.out w]
puts $out "E A L ux"
puts $out [format "%.10g %.10g %.10g %.10g" $E $A [pset L] [nodeDisp 2 1]]
close $out
