# SPDX-License-Identifier: MIT
# Energy balance of the three-span bridge over the whole run (verification), for the
# three cases at the default settings.
#
#   dabs verification/bridge/energy.tcl ?motion? ?dt? ?integrator?    (writes energy.md here)
#
# Relative formulation, from the state after the dead load: the equations of motion
#   M a + C_R v + f(u, v) = P_g - M r a_g(t)
# dotted with the displacement increments and summed over the run give
#   E_in + W_g = E_k + W_R + W_el
# with E_in = -sum (M r a_g) . du, the ground-motion input (a_g from getLoadFactor of the two
# UniformExcitation patterns, M from nodeMass: every mass of the bridge is a nodal mass);
# W_g = sum P_g . du, the work of the dead load held constant; E_k = v.M.v / 2 (translations and
# the rotary inertia of girders, caps and footings); W_R the work of
# the Rayleigh forces (eleResponse dampingForces); W_el = sum over the elements of their own
# resisting forces (eleForce) on their nodal displacement increments: strain energy plus the
# hysteresis of bearings and pier hinges, foundation dashpots, contact springs, dashpots and
# friction, restrainers and bumpers. Every term is a trapezoid sum over the steps, computed here
# from quantities the program reports, node by node and element by element.
#
# What it checks:
# - the balance closes: for Newmark average acceleration the discrete balance is exact when every
#   step is in equilibrium (the trapezoid of the acceleration term is exactly the change of E_k),
#   so the residual measures the equilibrium left in the converged steps, the scatter of element
#   forces through the rigid links, and whether the Rayleigh, mass and input terms are the ones
#   the analysis used; it must stay below 1e-4 of the largest input;
# - Rayleigh damping does not leak into the bearings, the contact pairs or the devices: their
#   dampingForces stay zero for the whole run;
# - the contact pairs' own energy accounts (friction work from the plastic slip, dashpot power)
#   equal the work of their forces when the joints are open at the end (no spring energy left).
set here [file dirname [info script]]
set ::bridgeLibraryOnly 1
source [file join $here bridge.tcl]
source [file join $here .. lib check.tcl]
# The balance over the motion itself (the input reads the ground acceleration of every step)
set tailDuration 0.0

set motion     [expr {$argc > 0 ? [lindex $argv 0] : "auto"}]
set dt         [expr {$argc > 1 ? [lindex $argv 1] : $defaultDt}]
set integrator [expr {$argc > 2 ? [lindex $argv 2] : $defaultIntegrator}]

# Element groups of the bridge, from the tags bridge.tcl gave them (any number of spans).
proc groupOf {e} {
  if {![info exists ::groupTable]} {
    foreach g $::girderEles { set ::groupTable($g) girders }
    foreach list $::poundingEles { foreach c $list { set ::groupTable($c) contact } }
    for {set j 1} {$j < $::nSpans} {incr j} { foreach k {1 2} { set ::groupTable([expr {[deviceTag $j] + $k}]) devices } }
    foreach b [bearingElements] { set ::groupTable($b) bearings }
    foreach e $::endEles { set ::groupTable($e) ends }
    for {set p 1} {$p <= $::nSpans + 1} {incr p} {
      foreach k {1 2 3 4} g {foundation hinges piers piers} { set ::groupTable([expr {[pierBase $p] + $k}]) $g }
    }
  }
  return $::groupTable($e)
}
set ::groups {foundation hinges piers bearings girders contact devices ends}

proc vdot {a b} {
  set s 0.0
  foreach x $a y $b { set s [expr {$s + $x * $y}] }
  return $s
}

# Called by runCase before the first step (initialises) and after every converged step.
proc energyStep {} {
  global g
  upvar #0 E E
  set t [getTime %.17g]
  set ag [list [getLoadFactor 11] [getLoadFactor 12]]
  set disp [dict create]
  foreach n $E(nodes) { dict set disp $n [nodeDisp $n] }
  set forces [dict create]; set rayleigh [dict create]
  foreach e $E(elements) {
    dict set forces $e [eleForce $e]
    dict set rayleigh $e [eleResponse $e dampingForces]
  }
  if {![info exists E(disp)]} {
    foreach k {in g k R} { set E($k) 0.0 }
    foreach grp $::groups { set E(el,$grp) 0.0 }
    set E(rayleighOutside) 0.0
  } else {
    # input and dead-load work, nodal masses
    set dIn 0.0; set dG 0.0
    foreach n $E(massNodes) {
      lassign [dict get $disp $n] x1 y1 z1
      lassign [dict get $E(disp) $n] x0 y0 z0
      lassign $E(mass,$n) mx my mz
      set dIn [expr {$dIn - $mx * 0.5 * ([lindex $E(ag) 0] + [lindex $ag 0]) * ($x1 - $x0)
                          - $my * 0.5 * ([lindex $E(ag) 1] + [lindex $ag 1]) * ($y1 - $y0)}]
      set dG [expr {$dG - $mz * $g * ($z1 - $z0)}]
    }
    set E(in) [expr {$E(in) + $dIn}]
    set E(g) [expr {$E(g) + $dG}]
    # element work and Rayleigh work
    foreach e $E(elements) {
      set du {}
      foreach n $E(nodes,$e) {
        foreach a [dict get $disp $n] b [dict get $E(disp) $n] { lappend du [expr {$a - $b}] }
      }
      set f [dict get $forces $e]; set f0 [dict get $E(forces) $e]
      set r [dict get $rayleigh $e]; set r0 [dict get $E(rayleigh) $e]
      set grp $E(group,$e)
      set E(el,$grp) [expr {$E(el,$grp) + 0.5 * ([vdot $f $du] + [vdot $f0 $du])}]
      set dR [expr {0.5 * ([vdot $r $du] + [vdot $r0 $du])}]
      set E(R) [expr {$E(R) + $dR}]
      if {$grp in {bearings contact devices foundation ends}} {
        foreach x $r { set E(rayleighOutside) [expr {max($E(rayleighOutside), abs($x))}] }
      }
    }
  }
  set ke 0.0
  foreach n $E(massNodes) {
    foreach m $E(mass,$n) v [nodeVel $n] { set ke [expr {$ke + 0.5 * $m * $v * $v}] }
  }
  set E(k) $ke
  set E(disp) $disp; set E(forces) $forces; set E(rayleigh) $rayleigh; set E(ag) $ag
  set el 0.0
  foreach grp $::groups { set el [expr {$el + $E(el,$grp)}] }
  set E(balance) [expr {$E(in) + $E(g) - $E(k) - $E(R) - $el}]
  set E(maxIn) [expr {max([info exists E(maxIn)] ? $E(maxIn) : 0.0, abs($E(in)))}]
  set E(maxResidual) [expr {max([info exists E(maxResidual)] ? $E(maxResidual) : 0.0, abs($E(balance)))}]
}

# The model exists only inside runCase; the first call of energyStep (before the first step)
# lists nodes, masses and elements.
proc energyStart {} {
  upvar #0 E E
  array unset E
  array unset ::groupTable   ;# a new model for each case
  set E(nodes) [getNodeTags]
  set E(elements) [getEleTags]
  set E(massNodes) {}
  foreach n $E(nodes) {
    set m [nodeMass $n]
    if {[tcl::mathfunc::max {*}$m] > 0.0} {
      lappend E(massNodes) $n
      set E(mass,$n) $m
    }
  }
  foreach e $E(elements) {
    set E(nodes,$e) [eleNodes $e]
    set E(group,$e) [groupOf $e]
  }
  interp alias {} energyHook {} energyStep
  energyStep
}
proc energyFirst {} {
  interp alias {} energyHook {} energyStart
}

set md [open energy.md w]
puts $md "# Energy balance of the bridge ($integrator, dt $dt s)\n"
puts $md "Energies in kJ at the end of the run (kN m); relative formulation from the dead-load state.\n"
puts $md "| case | input E_in | dead load W_g | kinetic E_k | Rayleigh W_R | foundation | pier hinges | pier elastic | bearings | girders | contact | devices | beyond the end piers | residual | max residual / max input |"
puts $md "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
foreach case {nopound pound countermeasure} {
  energyFirst
  set r [runCase $case 1.0 $dt $integrator $defaultTol $motion "" energyHook]
  check "$case: run completed" [dict get $r completed] 1 0
  set ratio [expr {$E(maxResidual) / $E(maxIn)}]
  puts [format "%s: E_in %.1f, W_g %.1f, E_k %.1f, W_R %.1f, W_el %s, residual %.3g (max %.3g of max input %.1f)" \
      $case $E(in) $E(g) $E(k) $E(R) [join [lmap grp $::groups {format %s=%.1f $grp $E(el,$grp)}] " "] \
      $E(balance) $E(maxResidual) $E(maxIn)]
  if {$integrator eq "Newmark"} {
    checkAbs "$case: max |energy residual| / max |input| over the run" $ratio 0.0 1e-4
  }
  checkAbs "$case: largest Rayleigh force in bearings, contact, devices, foundation, beyond the end piers (kN)" $E(rayleighOutside) 0.0 0.0
  check "$case: bearings dissipate (work of their forces > 0)" [expr {$E(el,bearings) > 0.0}] 1 0
  if {$case ne "nopound"} {
    # contact accounts: all pairs open at the end, so their work is what they dissipated
    set dissipated 0.0; set open 1
    foreach list $::poundingEles {
      foreach e $list {
        set dissipated [expr {$dissipated + [lindex [eleResponse $e dissipatedEnergy] 0]}]
        if {[eleResponse $e status] != 0} { set open 0 }
      }
    }
    if {$open} {
      check "$case: contact work = friction + dashpot energy of the pairs" $E(el,contact) $dissipated 0.02
    } else {
      puts "NOTE    $case: a contact pair is closed at the end; contact accounts not compared"
    }
  }
  puts $md [format "| %s | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.2f | %.1e |" \
      $case $E(in) $E(g) $E(k) $E(R) $E(el,foundation) $E(el,hinges) $E(el,piers) $E(el,bearings) \
      $E(el,girders) $E(el,contact) $E(el,devices) $E(el,ends) $E(balance) $ratio]
}
close $md
finish
