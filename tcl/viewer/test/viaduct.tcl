# SPDX-License-Identifier: MIT
# A long synthetic viaduct for the viewer's browser test (viewer.test.mjs): the first view must
# frame the whole bridge and the joint labels must not overlap, at any number of spans. Run as
#   dabs viaduct.tcl outDir spans
# Units kN, m, t, s. `spans` simply supported 40 m girders (elasticBeamColumn) sit on piers
# (elasticBeamColumn, heights 8 to 14 m so that the joints move differently) through elastic
# zeroLength links; a 0.1 m joint separates neighbouring girders above each inner pier. A 1 Hz sine
# along x shakes it for 0.4 s. Writes outDir/viaduct<spans>.html.
set out [lindex $argv 0]
set spans [lindex $argv 1]
file mkdir $out
set L 40.0
set joint 0.1

model basic -ndm 3 -ndf 6
geomTransf Linear 1 0.0 1.0 0.0
geomTransf Linear 2 0.0 0.0 1.0
uniaxialMaterial Elastic 1 2.0e5
uniaxialMaterial Elastic 2 1.0e8
set piers {}
for {set k 0} {$k <= $spans} {incr k} {
  set x [expr {$k * $L}]
  set h [expr {8.0 + 2.0 * ($k % 4)}]
  node [expr {1000 + $k}] $x 0.0 0.0
  node [expr {2000 + $k}] $x 0.0 $h
  fix [expr {1000 + $k}] 1 1 1 1 1 1
  element elasticBeamColumn [expr {1000 + $k}] [expr {1000 + $k}] [expr {2000 + $k}] 3.0 3.0e7 1.25e7 1.0 0.7 0.7 1
  lappend piers [expr {1000 + $k}]
}
set girders {}
set links {}
set gaps {}
for {set s 0} {$s < $spans} {incr s} {
  set x0 [expr {$s * $L + ($s > 0 ? 0.5 * $joint : 0.0)}]
  set x1 [expr {($s + 1) * $L - ($s + 1 < $spans ? 0.5 * $joint : 0.0)}]
  set a [expr {3000 + 2 * $s}]
  set b [expr {3001 + 2 * $s}]
  set za [expr {8.0 + 2.0 * ($s % 4)}]
  set zb [expr {8.0 + 2.0 * (($s + 1) % 4)}]
  node $a $x0 0.0 $za -mass 200.0 200.0 200.0 0.0 0.0 0.0
  node $b $x1 0.0 $zb -mass 200.0 200.0 200.0 0.0 0.0 0.0
  element elasticBeamColumn [expr {3000 + $s}] $a $b 6.0 3.0e7 1.25e7 5.0 2.0 40.0 2
  lappend girders [expr {3000 + $s}]
  foreach {n p} [list $a [expr {2000 + $s}] $b [expr {2001 + $s}]] {
    element zeroLength [expr {4000 + $n - 3000}] $p $n -mat 1 1 2 2 2 2 -dir 1 2 3 4 5 6
    lappend links [expr {4000 + $n - 3000}]
  }
  if {$s > 0} { lappend gaps [list "J$s" [expr {$a - 1}] $a] }
}

recorder Viewer -file [file join $out viaduct$spans.html] -title "viaduct of $spans spans" -plots {
  {"first girder end x" node 3001 1 disp}
} -beamSection [list [list rect 10.0 2.5 {*}$girders] [list circle 2.0 {*}$piers]] -gaps $gaps

timeSeries Trig 1 0.0 10.0 1.0 -factor 3.0
pattern UniformExcitation 1 1 -accel 1
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-8 20
algorithm Linear
integrator Newmark 0.5 0.25
analysis Transient
set ok [analyze 20 0.02]
if {$ok != 0} { error "analysis failed at t = [getTime %.17g]" }
puts "viaduct of $spans spans: 20 steps to t = [getTime %.17g]"
