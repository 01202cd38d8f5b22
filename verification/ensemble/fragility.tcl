# SPDX-License-Identifier: MIT
# Lognormal fragility curves P(DS | IM = x) = Phi((ln x - ln theta) / beta), fitted by maximum
# likelihood to runs that each did (1) or did not (0) exceed a damage state at their intensity x:
# the binomial likelihood of Baker (2015, "Efficient analytical fragility function fitting using
# dynamic structural analysis", Earthquake Spectra 31(1):579-599, eq. 11), written per run so
# that the runs of an incremental dynamic analysis need not share intensity levels. The maximum
# is found by Fisher scoring of the equivalent probit model Phi(a + b ln x) (theta = exp(-a/b),
# beta = 1/b; McCullagh and Nelder, Generalized Linear Models, 2nd ed., 1989, section 4.4).
#
#   source fragility.tcl
#   fragility::fit {x1 y1 x2 y2 ...} ?weights?   -> dict theta beta status n exceed
#   fragility::probability theta beta x          -> P(DS | IM = x)
#   fragility::Phi z                             -> standard normal distribution function
#
# status: fit (both parameters estimated) | none (no run exceeded: theta above every x) | all
# (every run exceeded: theta below every x) | separated (the exceeding runs all have larger x than
# the others: the likelihood grows without bound as beta -> 0; theta is the geometric mean of the
# two x that bracket the jump and beta 0).

# The incremental-dynamic-analysis fit (Baker 2015, section "IDA", eqs. 3 and 4): each motion is
# scaled up until it first exceeds the damage state; the intensities IM_i at which the n motions
# do so are taken as lognormal, theta = exp(mean ln IM_i), beta = the standard deviation of
# ln IM_i (divisor n - 1). A motion that never exceeds within its ladder is censored: it is left
# out and counted (the fit then says nothing of it, and its median is biased low).
#
#   fragility::idaFit {im1 im2 ...}                        -> dict theta beta n
#   fragility::bootstrap {im1 ...} ?samples? ?seed? ?p?    -> dict of the p and 1 - p quantiles of
#                                                            theta and beta over resampled sets
#                                                            (thetaLow thetaHigh betaLow betaHigh)

namespace eval fragility {
  variable maxIterations 100
  variable tolerance 1e-12
}

# Standard normal distribution function by Marsaglia's series (G. Marsaglia, "Evaluating the
# normal distribution", J. Statistical Software 11(4), 2004): Phi(z) = 1/2 + phi(z) (z + z^3/3 +
# z^5/(3 5) + ...), absolute error about 1e-15 for |z| < 8; beyond, 0 or 1 to double precision.
proc fragility::Phi {z} {
  if {$z < -8.0} { return 0.0 }
  if {$z > 8.0} { return 1.0 }
  set sum $z
  set term $z
  set z2 [expr {$z * $z}]
  for {set i 3} {$i < 400} {incr i 2} {
    set term [expr {$term * $z2 / $i}]
    set next [expr {$sum + $term}]
    if {$next == $sum} { break }
    set sum $next
  }
  return [expr {0.5 + $sum * exp(-0.5 * $z2 - 0.91893853320467274178)}]
}

# Standard normal density.
proc fragility::phi {z} { return [expr {exp(-0.5 * $z * $z) / sqrt(2.0 * acos(-1.0))}] }

proc fragility::probability {theta beta x} {
  if {$beta <= 0.0} { return [expr {$x >= $theta ? 1.0 : 0.0}] }
  return [Phi [expr {log($x / $theta) / $beta}]]
}

# Fits theta and beta to pairs {x y ...}: x > 0 the intensity, y the fraction of runs at x that
# exceeded (0 or 1 for one run); weights (default 1 each) the number of runs each pair stands for.
proc fragility::fit {pairs {weights {}}} {
  variable maxIterations
  variable tolerance
  set u {}; set y {}; set w {}
  set k 0
  foreach {x yi} $pairs {
    if {$x <= 0.0} { error "fragility::fit: intensity must be positive, got $x" }
    lappend u [expr {log($x)}]
    lappend y [expr {double($yi)}]
    lappend w [expr {[llength $weights] ? double([lindex $weights $k]) : 1.0}]
    incr k
  }
  set n 0.0; set exceed 0.0
  foreach yi $y wi $w { set n [expr {$n + $wi}]; set exceed [expr {$exceed + $wi * $yi}] }
  set result [dict create n $n exceed $exceed]
  if {$exceed <= 0.0} { return [dict merge $result [dict create status none theta Inf beta NaN]] }
  if {$exceed >= $n} { return [dict merge $result [dict create status all theta 0.0 beta NaN]] }
  # Complete separation: every exceeding run above every other one.
  set maxNo -Inf; set minYes Inf; set separated 1
  foreach ui $u yi $y {
    if {$yi > 0.0 && $yi < 1.0} { set separated 0 }
    if {$yi == 0.0 && $ui > $maxNo} { set maxNo $ui }
    if {$yi == 1.0 && $ui < $minYes} { set minYes $ui }
  }
  # (also quasi-complete: the largest 0 and the smallest 1 at the same x)
  if {$separated && $maxNo <= $minYes} {
    return [dict merge $result [dict create status separated theta [expr {exp(0.5 * ($maxNo + $minYes))}] beta 0.0]]
  }
  # Start: median at the weighted mean of ln x, dispersion their spread.
  set mean 0.0
  foreach ui $u wi $w { set mean [expr {$mean + $wi * $ui / $n}] }
  set var 0.0
  foreach ui $u wi $w { set var [expr {$var + $wi * ($ui - $mean) ** 2 / $n}] }
  set s [expr {max(sqrt($var), 0.1)}]
  set b [expr {1.0 / $s}]
  set a [expr {-$mean * $b}]
  set converged 0
  # Nearly separated data drive b up without bound until the arithmetic overflows: reported as
  # separated, like the exact case.
  if {[catch {scoring $u $y $w a b} converged]} { set converged 0 }
  if {!$converged || $b <= 0.0 || 1.0 / $b < 1e-6} {
    return [dict merge $result [dict create status separated theta [expr {exp(-$a / $b)}] beta 0.0]]
  }
  return [dict merge $result [dict create status fit theta [expr {exp(-$a / $b)}] beta [expr {1.0 / $b}]]]
}

# Fisher scoring of the probit model from (a, b); sets them to the estimate and returns 1 when it
# converged.
proc fragility::scoring {u y w aName bName} {
  variable maxIterations
  variable tolerance
  upvar 1 $aName a $bName b
  set converged 0
  for {set it 0} {$it < $maxIterations && !$converged} {incr it} {
    # Fisher scoring = iteratively reweighted least squares on the working response z.
    set S0 0.0; set S1 0.0; set S2 0.0; set T0 0.0; set T1 0.0
    foreach ui $u yi $y wi $w {
      set eta [expr {$a + $b * $ui}]
      set p [Phi $eta]
      set p [expr {min(max($p, 1e-300), 1.0 - 1e-16)}]
      set d [phi $eta]
      if {$d < 1e-300} { set d 1e-300 }
      set wt [expr {$wi * $d * $d / ($p * (1.0 - $p))}]
      set z [expr {$eta + ($yi - $p) / $d}]
      set S0 [expr {$S0 + $wt}]; set S1 [expr {$S1 + $wt * $ui}]; set S2 [expr {$S2 + $wt * $ui * $ui}]
      set T0 [expr {$T0 + $wt * $z}]; set T1 [expr {$T1 + $wt * $ui * $z}]
    }
    set det [expr {$S0 * $S2 - $S1 * $S1}]
    if {$det <= 0.0} { break }
    set aNew [expr {($S2 * $T0 - $S1 * $T1) / $det}]
    set bNew [expr {($S0 * $T1 - $S1 * $T0) / $det}]
    set change [expr {abs($aNew - $a) + abs($bNew - $b)}]
    set a $aNew; set b $bNew
    if {$change < $tolerance * (1.0 + abs($a) + abs($b))} { set converged 1 }
  }
  return $converged
}

proc fragility::idaFit {ims} {
  set n [llength $ims]
  if {$n == 0} { return [dict create theta NaN beta NaN n 0] }
  set mean 0.0
  foreach x $ims {
    if {$x <= 0.0} { error "fragility::idaFit: intensity must be positive, got $x" }
    set mean [expr {$mean + log($x) / $n}]
  }
  set var 0.0
  foreach x $ims { set var [expr {$var + (log($x) - $mean) ** 2}] }
  set beta NaN
  if {$n > 1} { set beta [expr {sqrt($var / ($n - 1))}] }
  return [dict create theta [expr {exp($mean)}] beta $beta n $n]
}

# Bootstrap (Efron and Tibshirani 1993, percentile intervals): the motions resampled with
# replacement `samples` times (a linear congruential generator with the given seed, so that the
# bands are the same on every run and machine), the fit repeated on each, and the p and 1 - p
# quantiles of theta and beta over the samples.
proc fragility::bootstrap {ims {samples 1000} {seed 12345} {p 0.05}} {
  set n [llength $ims]
  if {$n < 2} { return [dict create thetaLow NaN thetaHigh NaN betaLow NaN betaHigh NaN] }
  set state $seed
  set thetas {}; set betas {}
  for {set b 0} {$b < $samples} {incr b} {
    set pick {}
    for {set i 0} {$i < $n} {incr i} {
      # Numerical Recipes' 32-bit generator (ranqd1): a = 1664525, c = 1013904223
      set state [expr {(1664525 * $state + 1013904223) % 4294967296}]
      lappend pick [lindex $ims [expr {$state * $n / 4294967296}]]
    }
    set f [idaFit $pick]
    lappend thetas [dict get $f theta]
    lappend betas [dict get $f beta]
  }
  set thetas [lsort -real $thetas]; set betas [lsort -real $betas]
  set lo [expr {int(floor($p * ($samples - 1)))}]
  set hi [expr {int(ceil((1.0 - $p) * ($samples - 1)))}]
  return [dict create thetaLow [lindex $thetas $lo] thetaHigh [lindex $thetas $hi] \
      betaLow [lindex $betas $lo] betaHigh [lindex $betas $hi]]
}
