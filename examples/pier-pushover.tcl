# SPDX-License-Identifier: MIT
# Pushover of a circular reinforced-concrete pier (units kN, m, s, t): a 10 m cantilever, D = 2 m,
# one force-based element with a fiber section, axial load 10 % of f'c Ag, pushed sideways by
# displacement control to 6 % drift. Prints the capacity curve's first yield and peak (base shear,
# drift) and writes the curve to pier-pushover.txt.
set H 10.0; set D 2.0; set cover 0.075; set pi [expr {acos(-1.0)}]   ;# height, diameter, cover (m)
model basic -ndm 3 -ndf 6                             ;# 3D frame: 6 dofs a node
# Materials (kPa): confined core, unconfined cover (Concrete02: f'c eps0 f'cu epsU lambda ft Ets),
# reinforcing steel (Steel02: fy E b R0 cR1 cR2)
uniaxialMaterial Concrete02 1 -40000.0 -0.0025 -8000.0 -0.02 0.1 3000.0 1.5e6
uniaxialMaterial Concrete02 2 -30000.0 -0.002  -5000.0 -0.005 0.1 2500.0 1.2e6
uniaxialMaterial Steel02    3 400000.0 2.0e8 0.01 18.0 0.925 0.15
set rCore [expr {$D/2 - $cover}]; set rBar [expr {$rCore - 0.02}]   ;# core radius, bar circle radius
# Fiber section: core and cover as circular patches, 40 bars of 32 mm (0.000804 m^2) on a circle;
# -GJ gives the (elastic) torsional stiffness a 3D section needs
section Fiber 1 -GJ [expr {1.04e7*$pi*pow($D,4)/32}] {
  patch circ 1 16 8 0.0 0.0 0.0 $rCore 0.0 360.0       ;# core: 16 sectors x 8 rings
  patch circ 2 16 2 0.0 0.0 $rCore [expr {$D/2}] 0.0 360.0   ;# cover: 16 x 2
  layer circ 3 40 0.000804 0.0 0.0 $rBar 0.0 351.0     ;# bars every 9 degrees
}
node 1 0 0 0; node 2 0 0 $H; fix 1 1 1 1 1 1 1       ;# base fixed, top free
geomTransf PDelta 1 1.0 0.0 0.0                        ;# P-Delta; local x-z plane contains X
beamIntegration Lobatto 1 1 5                          ;# 5 integration points, section 1 at the base
element forceBeamColumn 1 1 2 1 1
# Gravity first: axial load 0.1 f'c Ag in 10 load steps, then held constant
set P [expr {0.1*30000.0*$pi*$D*$D/4}]
timeSeries Constant 1; pattern Plain 1 1 { load 2 0 0 [expr {-$P}] 0 0 0 }
constraints Plain; numberer Plain; system BandGeneral
test NormDispIncr 1.0e-8 50; algorithm Newton
integrator LoadControl 0.1; analysis Static
if {[analyze 10] != 0} { puts "FAILED: gravity load"; exit 1 }
loadConst -time 0.0
# Push: a reference load in X whose factor the displacement control finds, 5 mm per step
timeSeries Linear 2; pattern Plain 2 2 { load 2 1.0 0 0 0 0 0 }
set du 0.005; set target [expr {0.06*$H}]; set ey [expr {400000.0/2.0e8}]   ;# bar yield strain
integrator DisplacementControl 2 1 $du
set out [open pier-pushover.txt w]; puts $out "# drift(%) base_shear(kN)"
set yield {}; set peak {0 0}
while {[nodeDisp 2 1] < $target - 1e-9} {
  if {[analyze 1] != 0} {                             ;# a hard step: ten smaller ones, more iterations
    integrator DisplacementControl 2 1 [expr {$du/10}]; test NormDispIncr 1.0e-8 200
    for {set k 0} {$k < 10} {incr k} { if {[analyze 1] != 0} { puts "FAILED at [nodeDisp 2 1] m"; exit 1 } }
    integrator DisplacementControl 2 1 $du; test NormDispIncr 1.0e-8 50
  }
  reactions                                           ;# so nodeReaction returns the base forces
  set V [expr {-[nodeReaction 1 1]}]; set drift [expr {100*[nodeDisp 2 1]/$H}]
  puts $out [format "%.3f %.1f" $drift $V]
  # First yield: the extreme tension bar (at -X, local z = -rBar) reaches fy/E
  set eps [lindex [eleResponse 1 section 1 fiber 0.0 [expr {-$rBar}] 3 stressStrain] 1]
  if {$yield eq {} && $eps >= $ey} { set yield [list $drift $V] }
  if {$V > [lindex $peak 1]} { set peak [list $drift $V] }
}
close $out
if {$yield eq {} || [lindex $peak 1] <= [lindex $yield 1]} { puts "FAILED: no yield before the peak"; exit 1 }
puts [format "first yield of a bar: base shear %.0f kN at drift %.2f %%" [lindex $yield 1] [lindex $yield 0]]
puts [format "peak:                 base shear %.0f kN at drift %.2f %%" [lindex $peak 1] [lindex $peak 0]]
puts [format "end:                  base shear %.0f kN at drift %.2f %%" $V $drift]
puts [format "peak over first yield: base shear %.2f, drift %.2f" \
    [expr {[lindex $peak 1]/[lindex $yield 1]}] [expr {[lindex $peak 0]/[lindex $yield 0]}]]
