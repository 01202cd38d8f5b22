# SPDX-License-Identifier: MIT
# Closed forms shared by the pounding verification scripts (sourced, not run by ctest).

set ::pi [expr {acos(-1.0)}]

# Damping ratio for a restitution coefficient e (Zhu, Abe and Fujino 2002):
# xi = -ln e / sqrt(pi^2 + ln^2 e).
proc dampingRatio {e} {
  if {$e >= 1.0} { return 0.0 }
  set l [expr {log($e)}]
  return [expr {-$l / sqrt($::pi*$::pi + $l*$l)}]
}

# Exit/approach speed ratio of a linear spring-dashpot impact whose force may not pull: the
# contact ends when K x + C x' = 0, at w_d t* = pi - atan2(2 xi r, 1 - 2 xi^2), r = sqrt(1 - xi^2);
# e_eff = exp(-xi w t*) (xi/r sin(w_d t*) - cos(w_d t*)). With pulling allowed it would be e.
proc effectiveRestitution {xi} {
  if {$xi <= 0.0} { return 1.0 }
  set r [expr {sqrt(1.0 - $xi*$xi)}]
  set phase [expr {$::pi - atan2(2.0*$xi*$r, 1.0 - 2.0*$xi*$xi)}]
  return [expr {exp(-$xi*$phase/$r) * ($xi/$r*sin($phase) - cos($phase))}]
}

# Runs `analyze 1 dt` until the time reaches tEnd or `stop` (a script) returns true; returns the
# number of failed steps (0 when all converged).
proc runUntil {dt tEnd {stop {expr 0}}} {
  set failed 0
  while {[getTime %.17g] < $tEnd - 0.5*$dt} {
    if {[analyze 1 $dt] != 0} { incr failed; break }
    if {[uplevel #0 $stop]} { break }
  }
  return $failed
}
