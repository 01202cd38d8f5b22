# Compatibility input: the force-based element's local iteration where Newton on the current
# section flexibilities cycles. Two RC columns (2D, one forceBeamColumn each, 5 Lobatto points,
# Concrete01 core and cover with a descending branch, Steel01 bars whose tangent jumps from E to
# bE at yield) under 8 % axial load, tied at the top by a stiff beam and shaken by a sine ground
# acceleration that yields the bars in both directions, to a drift of 6 % (Newmark, Newton,
# NormDispIncr 1e-8).
# At the bars' kinks the element's Newton iteration cycles; OpenSees then iterates with the initial
# section flexibilities, and its test of convergence is absolute (|dv . dq| < 1e-12). Each row:
# time, top displacement, the first column's base shear and moment (units m, kN, t, s).
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 6.0 0.0
node 3 0.0 3.5 -mass 60.0 60.0 0.0
node 4 6.0 3.5 -mass 60.0 60.0 0.0
fix 1 1 1 1
fix 2 1 1 1
uniaxialMaterial Concrete01 1 -34000.0 -0.004 -24000.0 -0.014
uniaxialMaterial Concrete01 2 -27600.0 -0.002 0.0 -0.006
uniaxialMaterial Steel01 3 420000.0 2.0e8 0.01
# 0.5 m square, 50 mm cover, 4 bars of 25 mm on each face.
section Fiber 1 {
  patch rect 1 12 1 -0.2 -0.2 0.2 0.2
  patch rect 2 12 1 -0.25 0.2 0.25 0.25
  patch rect 2 12 1 -0.25 -0.25 0.25 -0.2
  patch rect 2 2 1 -0.25 -0.2 -0.2 0.2
  patch rect 2 2 1 0.2 -0.2 0.25 0.2
  layer straight 3 4 0.000491 0.2 0.2 0.2 -0.2
  layer straight 3 4 0.000491 -0.2 0.2 -0.2 -0.2
}
geomTransf PDelta 1
geomTransf Linear 2
element forceBeamColumn 1 1 3 1 Lobatto 1 5
element forceBeamColumn 2 2 4 1 Lobatto 1 5
element elasticBeamColumn 3 3 4 0.3 3.0e7 0.02 2
timeSeries Linear 1
pattern Plain 1 1 {
  load 3 0.0 -680.0 0.0
  load 4 0.0 -680.0 0.0
}
constraints Plain; numberer RCM; system BandGeneral
test NormDispIncr 1.0e-8 20; algorithm Newton
integrator LoadControl 0.1; analysis Static
analyze 10
loadConst -time 0.0
wipeAnalysis
# 1.0 g at 1.25 Hz, growing over the first 2 s.
set values {}
for {set k 0} {$k <= 400} {incr k} {
  set t [expr {0.01*$k}]
  lappend values [expr {min($t/2.0, 1.0)*1.0*9.81*sin(2.0*acos(-1.0)*1.25*$t)}]
}
timeSeries Path 2 -dt 0.01 -values $values
pattern UniformExcitation 2 1 -accel 2
rayleigh 0.3 0.0 0.002 0.0
constraints Plain; numberer RCM; system BandGeneral
test NormDispIncr 1.0e-8 20; algorithm Newton
integrator Newmark 0.5 0.25; analysis Transient
set out [open compat-forcebeam-strategies.out w]
puts $out "time topDisp shear moment"
for {set k 1} {$k <= 400} {incr k} {
  if {[analyze 1 0.01] != 0} { puts $out "failed at step $k"; break }
  set f [eleForce 1]
  puts $out [format "%.4f %.12g %.12g %.12g" [getTime] [nodeDisp 3 1] [lindex $f 0] [lindex $f 2]]
}
close $out
