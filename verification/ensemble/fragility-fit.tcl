# SPDX-License-Identifier: MIT
# The lognormal fragility fit of fragility.tcl against exact answers.
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] fragility.tcl]

# Phi against tabulated values (Abramowitz and Stegun, Handbook of Mathematical Functions, 1964,
# table 26.1: Phi(1) = 0.8413447461, Phi(2) = 0.9772498681, Phi(3) = 0.9986501020; and the
# quantiles Phi(1.959963985) = 0.975, Phi(-2.326347874) = 0.01).
check "Phi(0)" [fragility::Phi 0.0] 0.5 1e-15
check "Phi(1), A&S table 26.1" [fragility::Phi 1.0] 0.8413447461 1e-10
check "Phi(2), A&S table 26.1" [fragility::Phi 2.0] 0.9772498681 1e-10
check "Phi(3), A&S table 26.1" [fragility::Phi 3.0] 0.9986501020 1e-10
check "Phi(-1) = 1 - Phi(1)" [fragility::Phi -1.0] [expr {1.0 - 0.8413447461}] 1e-9
check "Phi(1.959963985) = 0.975" [fragility::Phi 1.959963985] 0.975 1e-9
check "Phi(-2.326347874) = 0.01" [fragility::Phi -2.326347874] 0.01 1e-8

# Stripes whose observed fractions are exactly Phi((ln x - ln theta)/beta) make the score of the
# likelihood zero at (theta, beta): the maximum likelihood estimate is theta and beta themselves.
set theta 0.8; set beta 0.45
set pairs {}; set weights {}
foreach z {-1.5 -0.5 0.0 0.7 1.8} {
  lappend pairs [expr {$theta * exp($beta * $z)}] [fragility::Phi $z]
  lappend weights 40
}
set f [fragility::fit $pairs $weights]
checkTrue "stripes: fitted" [expr {[dict get $f status] eq "fit"}]
check "stripes: theta recovered" [dict get $f theta] $theta 1e-9
check "stripes: beta recovered" [dict get $f beta] $beta 1e-9

# Single runs (0/1 each), symmetric about x = 1: at the maximum the median is 1 by symmetry.
set runs {0.25 0 0.5 0 0.7 1 0.8 0 1.0 0 1.0 1 1.25 1 1.4286 0 2.0 1 4.0 1}
set f [fragility::fit $runs]
check "symmetric runs: theta = 1 by symmetry" [dict get $f theta] 1.0 1e-3
checkTrue "symmetric runs: beta positive ([dict get $f beta])" [expr {[dict get $f beta] > 0.0}]
# The estimate maximises the likelihood: moving either parameter lowers it.
proc logLikelihood {runs theta beta} {
  set sum 0.0
  foreach {x y} $runs {
    set p [fragility::probability $theta $beta $x]
    set sum [expr {$sum + ($y ? log($p) : log(1.0 - $p))}]
  }
  return $sum
}
set best [logLikelihood $runs [dict get $f theta] [dict get $f beta]]
set lower 1
foreach {dt db} {0.05 0 -0.05 0 0 0.05 0 -0.05} {
  set other [logLikelihood $runs [expr {[dict get $f theta] * (1.0 + $dt)}] [expr {[dict get $f beta] * (1.0 + $db)}]]
  if {$other >= $best} { set lower 0 }
}
checkTrue "symmetric runs: the fit is a maximum of the likelihood" $lower

# Degenerate data are reported, not fitted.
checkTrue "no exceedance: status none" [expr {[dict get [fragility::fit {0.5 0 1.0 0}] status] eq "none"}]
checkTrue "all exceed: status all" [expr {[dict get [fragility::fit {0.5 1 1.0 1}] status] eq "all"}]
set f [fragility::fit {0.5 0 1.0 0 2.0 1 4.0 1}]
checkTrue "separated runs: status separated" [expr {[dict get $f status] eq "separated"}]
check "separated runs: theta between the last 0 and the first 1" [dict get $f theta] [expr {sqrt(2.0)}] 1e-12
# The IDA fit (Baker 2015, eqs. 3 and 4): intensities exp(mu + sigma z_i) with z_i of mean 0 and
# sample standard deviation 1 give theta = exp(mu) and beta = sigma exactly.
set zs {-1.2649110640673518 -0.6324555320336759 0.0 0.6324555320336759 1.2649110640673518}
set mu [expr {log(1.1)}]; set sigma 0.4
set f [fragility::idaFit [lmap z $zs {expr {exp($mu + $sigma * $z)}}]]
check "IDA fit: theta = exp(mean ln IM)" [dict get $f theta] 1.1 1e-12
check "IDA fit: beta = standard deviation of ln IM (n - 1)" [dict get $f beta] $sigma 1e-12
checkTrue "IDA fit: no motion, no fit" [expr {[dict get [fragility::idaFit {}] n] == 0}]
# Bootstrap: the band holds the full-sample estimate, is reproducible with its seed, and narrows
# when every motion is there four times (more data of the same spread).
set ims [lmap z $zs {expr {exp($mu + $sigma * $z)}}]
set band [fragility::bootstrap $ims 1000 7]
checkTrue "bootstrap: theta's band holds the estimate ([dict get $band thetaLow] .. [dict get $band thetaHigh])" \
    [expr {[dict get $band thetaLow] < 1.1 && 1.1 < [dict get $band thetaHigh]}]
checkTrue "bootstrap: the same seed gives the same band" [expr {$band eq [fragility::bootstrap $ims 1000 7]}]
set band4 [fragility::bootstrap [concat $ims $ims $ims $ims] 1000 7]
checkTrue "bootstrap: four times the motions, a narrower band" \
    [expr {[dict get $band4 thetaHigh] - [dict get $band4 thetaLow] < [dict get $band thetaHigh] - [dict get $band thetaLow]}]
# The standard error of ln theta is s / sqrt(n), s the spread of the data (the population's, of the
# five values repeated: sigma sqrt(4/5)): with 400 motions the 90 % band of ln theta is
# 2 x 1.645 s / 20 (the bootstrap's own noise aside, within 10 %)
set many {}
for {set i 0} {$i < 80} {incr i} { lappend many {*}$ims }
set band [fragility::bootstrap $many 1000 11]
check "bootstrap: 90 % band of ln theta with 400 motions = 2 x 1.645 s / sqrt(400)" \
    [expr {log([dict get $band thetaHigh]) - log([dict get $band thetaLow])}] [expr {2.0 * 1.645 * $sigma * sqrt(0.8) / 20.0}] 0.1

finish
