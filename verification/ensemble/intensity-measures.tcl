# SPDX-License-Identifier: MIT
# The intensity measures of intensity.tcl against published values for the project's records.
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] intensity.tcl]

# Chopra (Dynamics of Structures, section 6.4, fig. 6.4.1 and example 6.4): El Centro NS under
# g = 386.4 in/s^2, peak deformation D of elastic oscillators, in inches. Chopra integrates with
# linear acceleration and we with average acceleration at the record's 0.02 s: period errors of
# (w dt)^2 / 12 < 0.6 % here, so 2 %.
set TOL_CHOPRA 0.02
set file [recordPath elCentro.at2]
set h [intensity::recordHeader $file]
set duration [expr {[dict get $h npts] * [dict get $h dt]}]
foreach {T zeta D} {0.5 0.02 2.67 1.0 0.02 5.97 2.0 0.02 7.47 2.0 0.05 5.37} {
  set im [intensity::measures [list timeSeries Path 1 -filePath $file -factor 386.4] $T $zeta $duration [dict get $h dt]]
  check "El Centro D(T = $T s, zeta = $zeta), Chopra 6.4" [dict get $im sd] $D $TOL_CHOPRA
}
# Sa = (2 pi / T)^2 D, the pseudo-acceleration, in g from Chopra's D = 5.37 in at T = 2 s, 5 %.
check "El Centro Sa(2 s, 5 %) = (2 pi/T)^2 D / g" [expr {[dict get $im sa] / 386.4}] \
    [expr {(2.0 * acos(-1.0) / 2.0) ** 2 * 5.37 / 386.4}] $TOL_CHOPRA

# Peak ground velocity of Takatori EW by the trapezoid rule on the record as distributed: about
# 1.23 m/s (the shared data's README, an independent integration of the same file).
set file [recordPath RSN1120_KOBE_TAK090.AT2]
set h [intensity::recordHeader $file]
set im [intensity::measures [list timeSeries Path 1 -filePath $file -factor 9.81] 1.0 0.05 \
    [expr {[dict get $h npts] * [dict get $h dt]}] [dict get $h dt]]
check "Takatori EW PGV (m/s), trapezoid rule" [dict get $im pgv] 1.23 0.01

# The built-in pulse: its peak velocity at nu = 0 is Vp (Mavroeidis and Papageorgiou 2003, eq. 1
# at t = t0), here 0.8 m/s, sampled finely enough that the peak is caught to 1e-4.
set im [intensity::measures {timeSeries NearFaultPulse 1 -Tp 1.2 -Vp 0.8 -gamma 2.0 -nu 0.0 -t0 3.0} \
    1.0 0.05 8.0 0.0005]
check "pulse PGV = Vp at nu = 0" [dict get $im pgv] 0.8 1e-4
finish
