# Compatibility input: `timeSeries Path -dt -filePath` and `-fileTime -filePath` on record files
# that end in a non-numeric trailer, as PEER-processed records do ("*** End Data ***"). OpenSees
# reads numbers until the first that is not one and keeps those. A unit spring carries a load
# pattern of each series; each row: pseudo time (static load control) and the two displacements,
# i.e. the two series' factors.
wipe
set f [open compat-path-values.txt w]
puts $f "0.0 0.5 1.0 0.25\n-0.5 -1.0 0.0 0.75"
puts $f "0.4 0.2*** End Data ***"
puts $f "9.0 9.0 9.0"
close $f
set f [open compat-path-times.txt w]
puts $f "0.0 0.1 0.3 0.6 1.0 1.2 1.3 1.5 1.9 2.1"
puts $f "*** End Data ***"
puts $f "3.0 4.0"
close $f

model basic -ndm 1 -ndf 1
node 1 0.0; node 2 1.0; node 3 2.0
fix 1 1
uniaxialMaterial Elastic 1 1.0
element zeroLength 1 1 2 -mat 1 -dir 1
element zeroLength 2 1 3 -mat 1 -dir 1
timeSeries Path 1 -dt 0.2 -filePath compat-path-values.txt -factor 2.0
timeSeries Path 2 -fileTime compat-path-times.txt -filePath compat-path-values.txt
pattern Plain 1 1 { load 2 1.0 }
pattern Plain 2 2 { load 3 1.0 }
system BandGeneral; numberer Plain; constraints Plain; test NormDispIncr 1e-12 10
algorithm Newton; integrator LoadControl 0.05; analysis Static
set out [open compat-path-trailer.out w]
puts $out "time u2 u3"
for {set i 1} {$i <= 50} {incr i} {
  analyze 1
  puts $out [format "%.10g %.10g %.10g" [getTime] [nodeDisp 2 1] [nodeDisp 3 1]]
}
close $out
