# SPDX-License-Identifier: MIT
# Axial force-deformation histories of one circular elastomeric bearing (Kumar et al. 2014
# vertical law), shared by its two twins: elastomericx-vertical.tcl (dabs, yoshidaBearing
# -vertical kumar) and opensees-twins/elastomericx-vertical.tcl (OpenSees, ElastomericX). Each
# twin defines `makeBearing tag iNode jNode` and the bearing's data below, then sources this file.
# Units kN, m. The horizontal laws differ, so only the axial force N against the axial
# deformation u is written, at a horizontal offset held fixed (imposed first, then kept constant).
# Writes elastomericx-vertical.out: a header line per block, then "u N Mz_i" per step.

# Rubber and geometry (G, Kbulk in kN/m^2; lengths in m): Do 0.8, Di 0.1, 20 layers of 10 mm.
set G 800.0
set Kbulk 2.0e6
set Di 0.1
set Do 0.8
set ts 0.003
set tr 0.01
set nLayers 20
set kc 20.0
set phi 0.5
set ac 1.0

set out [open elastomericx-vertical.out w]

# Moves the top node's vertical dof through the targets in steps no longer than du and writes
# u, N and the local moment about z at node i (the P-Delta moment N d1/2: the rotations are held,
# so the rocking springs carry nothing) after each step.
proc axialPath {out targets du} {
  set u 0.0
  foreach target $targets {
    while {abs($target - $u) > 1e-12} {
      set step [expr {$target > $u ? min($du, $target - $u) : max(-$du, $target - $u)}]
      integrator DisplacementControl 2 3 $step
      if {[analyze 1] != 0} { error "axial step to [expr {$u + $step}] failed" }
      set u [expr {$u + $step}]
      puts $out [format "%.10g %.10g %.10g" [nodeDisp 2 3] [lindex [eleResponse 1 basicForce] 0] \
        [lindex [eleResponse 1 localForce] 5]]
    }
  }
}

# One block: a fresh bearing, the horizontal offset (global X = local y) imposed in 10 steps with
# the vertical force zero, then the axial path.
proc block {out name offset targets} {
  puts $out "# $name offset $offset"
  wipe
  model basic -ndm 3 -ndf 6
  node 1 0.0 0.0 0.0
  node 2 0.0 0.0 0.0
  fix 1 1 1 1 1 1 1
  fix 2 0 1 0 1 1 1
  makeBearing 1 1 2
  timeSeries Linear 1
  pattern Plain 1 1 {
    sp 2 1 $offset
  }
  constraints Transformation
  numberer Plain
  system BandGeneral
  test NormDispIncr 1.0e-12 50
  algorithm Newton
  integrator LoadControl 0.1
  analysis Static
  if {[analyze 10] != 0} { error "offset $offset failed" }
  loadConst -time 0.0
  pattern Plain 2 1 {
    load 2 0.0 0.0 1.0 0.0 0.0 0.0
  }
  axialPath $out $targets 0.0005
}

# Zero shear: tension past cavitation (uc = Fc/Kv0 = 0.78 mm), unloading, reloading past the
# largest tension (damaged cavitation strength), compression past the critical load and back.
block $out "tension and compression at zero shear" 0.0 {0.05 0.01 0.0 0.03 0.1 0.0 -0.02 0.0}
# Compression at a shear offset of Do/2 (Ar/A = 0.39): lower Kv and Pcr.
block $out "compression at offset Do/2" 0.4 {-0.03 -0.005 -0.03 0.0}
# Tension at the offset Do/2 (Kv and so uc = Fc/Kv change with the shear): cavitation, unloading,
# reloading past the largest tension.
block $out "tension at offset Do/2" 0.4 {0.03 0.0 0.05 0.0}
# Compression at a shear offset of 0.875 Do: Ar/A below 0.2, so Pcr = 0.2 Pcr0.
block $out "compression at offset 0.875 Do" 0.7 {-0.03 0.0}
close $out
