# SPDX-License-Identifier: MIT
# Three-span base-isolated steel bridge under a near-fault ground motion: the main job
# of DABS. A readable model that a user can copy and change: every dimension, material and
# device is a variable at the top, with its unit.
# One file on purpose (over 800 lines): the parameters, the model, the quantities followed and the
# run loop are what a user copies and changes together; the report, the findings against the
# paper and the checks are in tools/ (report.tcl, findings.tcl, checks.tcl).
#
#   dabs verification/bridge/bridge.tcl ?case? ?scale? ?dt? ?integrator? ?tol? ?motion? ?outDir? ?nSpans?
#
#   case        all (default: the three cases and the report) | nopound | pound | countermeasure
#   scale       factor on the ground motion (default 1.0)
#   dt          analysis time step, s (default 0.0025 from the speed study, tools/speed-study.tcl,
#               at any number of spans, see verification/bench/results/viaduct.md)
#   integrator  Newmark (average acceleration) | HHT (alpha = 0.95, OpenSees convention) (default Newmark)
#   tol         NormDispIncr tolerance, m (default from the speed study)
#   motion      auto (default: the Takatori record if found, else the fitted pulse) | record |
#               pulse | path/to/file.AT2
#   outDir      where the report, the CSV histories and the plots go (default ./bridge-out)
#   nSpans      number of spans (default 3, the paper's bridge; pier heights repeat as a pattern)
#
# Units: kN, m, s, t (tonne = kN s^2/m), kPa. Axes: X along the bridge, Y transverse, Z up.
#
# The model (see docs/case-study.md and report.md for the results):
#   PC1 ... PC4  (PC(n+1) for n spans) RC piers on pile-group foundations (springs + dashpots derived below), a fiber
#                forceBeamColumn plastic-hinge segment at the base, elastic segments above, a cap
#   G1 G2 G3     (G1 ... Gn) simply supported steel girders, elastic 3D beams with mass, each end on
#                bearingsPerEnd Yoshida high-damping-rubber bearings across the width (fitted set (a)
#                of verification/bearing/fitted-parameters.md) that drop onto their seats when they rupture
#   ends         beyond PC1 and PC(n+1): the next units' girders, or abutments (endCondition)
#   joints       expansion joints over PC2 and PC3 (every inner pier): point-to-surface pounding both ways between the
#                girder end faces (4-node faces rigidly tied to the girder end); countermeasure:
#                cable restrainers (tension) and rubber bumpers (compression) between the girder ends,
#                longitudinal and transverse, on both sides of the girders
#   damping      stiffness-proportional Rayleigh damping on the piers and girders only; bearings,
#                contact and the restrainers decline Rayleigh damping; foundation dashpots
#   motion       one horizontal component applied at angle $motionAngle to the bridge axis
#   stepping     dt, shortened to at most $contactDt while a joint is closed or closing and cut at
#                each predicted first contact (the driver's contactStepping)

# ---------------------------------------------------------------------------------------------
# Parameters
# ---------------------------------------------------------------------------------------------
set g 9.81                  ;# m/s^2
set pi [expr {acos(-1.0)}]

# Layout
set nSpans 3                ;# simply supported spans (a viaduct of any length: one joint per inner pier)
set spanLength 40.0         ;# m, pier axis to pier axis
set pierHeights {10.0 14.0 8.0 12.0} ;# m, PC1..PC4, top of footing to top of cap (bearing seat);
                            ;# the ground is uneven, the deck level: the piers differ, and so do
                            ;# the periods of the spans, which is what makes adjacent girders pound.
                            ;# nSpans + 1 heights, or a shorter list repeated as a pattern along
                            ;# the viaduct (pierHeight)
set jointGap 0.05           ;# m, expansion-joint gap between girder end faces over the inner piers
set bearingOffset 0.60      ;# m, bearing axis from the pier axis along X
set bearingHeight 0.30      ;# m, bottom to top plate of a bearing (rubber + steel plates)

# Steel girder with its RC deck (per span)
set girderMass 15.0         ;# t/m (steel, slab, pavement, barriers)
set girderA 0.60            ;# m^2 (steel-equivalent area)
set girderIvert 0.80        ;# m^4 (vertical bending)
set girderIlat 12.0         ;# m^4 (lateral bending, the deck slab)
set girderJ 0.50            ;# m^4
set steelE 2.0e8            ;# kPa
set steelG 7.7e7            ;# kPa
set girderDepth 2.5         ;# m, end-face height (girder + slab)
set girderWidth 10.0        ;# m, end-face width
set girderElements 4        ;# elastic elements between the bearings of a span (at most 8: the
                            ;# three-span numbers of girder 6 meet the devices' from 9 on)
set girderDamping 0.02      ;# damping ratio of the girders at their first vertical mode

# RC piers: circular, D = 2 m (the section of verification/piers/pier-pushover.tcl)
set pierD 2.0               ;# m
set pierCover 0.075         ;# m
set fcCore -40000.0         ;# kPa, confined core strength
set fcCover -30000.0        ;# kPa
set steelFy 400000.0        ;# kPa, reinforcing bars
set nBars 24                ;# longitudinal bars, together 40 bars of 32 mm (0.0322 m^2)
set barArea [expr {40 * 0.000804 / $nBars}] ;# m^2 per fiber
set coreRings 5             ;# fiber mesh: radial rings of the core, 12 sectors (speed: see README)
set integrationPoints 4     ;# Lobatto points of the fiber segment
set concreteE 2.5e7         ;# kPa, elastic segments
set concreteG 1.04e7        ;# kPa
set crackedFactor 0.7       ;# effective EI / gross EI of the elastic segments
set hingeLength 3.0         ;# m, fiber (forceBeamColumn) segment at the base
set concreteDensity 2.5     ;# t/m^3
set capMass 150.0           ;# t, pier cap (lumped at the pier top)
set capSize {3.0 10.0 2.0}  ;# m, cap length along X, width along Y, depth (for its rotary inertia)
set pierDamping 0.05        ;# damping ratio of the piers at their own cantilever period

# Foundation: footing on a 3 x 3 group of cast-in-place piles (Japan Road Association style)
set footingMass 400.0       ;# t
set footingSize {9.0 9.0 2.0} ;# m, footing plan X, Y and depth (for its rotary inertia)
set pileD 1.2               ;# m
set pileLength 20.0         ;# m
set pileE 2.5e7             ;# kPa
set pileSpacing 3.0         ;# m, centre to centre, both directions
set subgradeKh 20000.0      ;# kN/m^3, horizontal subgrade reaction coefficient k_h
set foundationDamping 0.10  ;# damping ratio of the foundation springs at the isolated period

# High-damping rubber bearings: bearingsPerEnd bearings across the width at each girder end, one
# under each main girder, so that the girder's yaw shows in the outer bearings' strains (1: one
# element per end stands for them all, with lumped torsion and roll springs at +-bearingRollArm)
set bearingArea 1.6         ;# m^2, total rubber area at one girder end (0.4 m^2, 632 mm square, each)
set bearingTr 0.20          ;# m, total rubber thickness
set rubberG 1000.0          ;# kPa, nominal shear modulus (for the vertical stiffness only)
set shapeFactor 10.0        ;# first shape factor S of one rubber layer
set bearingsPerEnd 4        ;# bearings across one girder end (1 ... 5)
set girderSpacing 2.5       ;# m, transverse spacing of the main girders (and of their bearings)
set bearingRollArm 3.0      ;# m, with bearingsPerEnd 1: transverse spacing / 2 of the lumped pair
# Rupture (past 300 % shear strain): the rubber carries nothing more and the girder end comes down
# by the bearing's height onto the bearing's lower plate on the pier cap, then rests and slides
# there with Coulomb friction (yoshidaBearing -afterFailure drop; the seat's stiffness is the
# bearing's own Kv, whose settlement under the weight, about 1 mm, is small against the drop)
set seatFriction {0.5 0.4}  ;# mu_s mu_k, steel plate on steel plate after rupture
# The bearings' vertical law: linear (default: Kv = Ec A / Tr, whatever the shear) or kumar
# (yoshidaBearing -vertical kumar -pDelta, docs/bearings.md: Kv falling with
# the shear offset, cavitation at 3 G A, buckling at the offset's critical load, and the axial
# force's P-Delta moments). For kumar each square pad is the circle of the same area (Do), its
# rubber layer tr = Do / (4 S) rounded to a whole number of layers in bearingTr
set bearingVertical linear
set rubberKbulk 2.0e6       ;# kPa, bulk modulus of rubber (2000 MPa, as Kumar et al. 2014 take it)
set shimThickness 0.0045    ;# m, steel shim between layers (ours: it sets only the height
                            ;# Tr + (n - 1) ts of the buckling load and the P-Delta lever)
# HDR set (a) of verification/bearing/fitted-parameters.md, fitted by `yoshida_calibration fit` to
# Bridgestone's X0.6 design curves (Geq within 2.0 % rms, Heq within 2.3 % rms from 10 % to 300 %
# shear strain): Y0 [MPa] U0 [strain] n alpha0 beta q gamma, per unit area and unit Tr
set hdr {0.435794 0.0683367 0.115167 0.831926 0.698464 0.0393774 0.000947439}
# Design shear strain of the bearings (250 %: the allowable shear strain of rubber bearings under
# level-2 motion, JRA Specifications for Highway Bridges Part V, the report's design limit); the
# linear parts that stand for the bearings' shear (torsion of a bearing pair, the isolated period
# that tunes the foundation dashpots) take the set's effective stiffness Keq at this amplitude
set bearingDesignStrain 2.5

# What lies beyond the end piers PC1 and PC(n+1) (the bridge is a unit of an elevated viaduct):
#   adjacent  the next units' girders (default): on each side a girder of the same span and mass on
#             its own bearings, resting on the end pier's free bearing line and, at its far end, on
#             the next pier (its cap on the pier's elastic lateral stiffness); one rigid body (its
#             flexure is left out: what it does to this unit is to pound on the end girder across
#             the joint gap and to load the end pier), with the same pounding and devices as a joint
#   abutment  the end supports are seat-type abutments (rigid, moving with the ground): the end
#             girders sit on bearings on the abutment seat and face the backwall across the joint
#             gap; the backwall and backfill are a bilinear spring (Caltrans SDC 1.7 section 7.8.1:
#             initial stiffness Ki = 28.7 kN/mm per m of width scaled by h/1.7 m, passive capacity
#             239 kPa x backwall area x h/1.7 m); no restrainers or bumpers there; PC1's and
#             PC(n+1)'s heights still set the deck level and the mean pier height
#   free      nothing (the girders' outer ends are free): the former model, for comparison
# The default is adjacent because the paper's bridge stands inside an elevated expressway: its
# end piers carry the neighbouring units' girders, and the unit's end joints pound on them.
set endCondition adjacent
set abutmentKi 28700.0      ;# kN/m per m of backwall width, for a 1.7 m (5.5 ft) high backwall
set abutmentPressure 239.0  ;# kPa, passive pressure for a 1.7 m high backwall (5.0 ksf)

# Pounding (Zhu, Abe and Fujino 2002): penalty K = EA/L of the girder, shared by the 8 pairs
# (times impactStiffnessFactor, 1 but for the sensitivity study); each pair takes its share of
# the two bodies' masses too (1/8), so that a flat impact of the whole face damps as one
# spring-dashpot EA/L with restitution e (with the whole masses on every pair the dashpots of
# the 8 pairs would add up to sqrt(8) times the damping: a restitution of 0.38 for e = 0.65,
# joint-restitution.tcl)
set impactStiffnessFactor 1.0
set restitution 0.65
# The impact law (nodeToSurface -law; docs/contact.md, "Impact laws"): kelvin (the paper's) by default;
# for the power laws hertz, hertzdamp (Muthukumar and DesRoches 2006) and jankowski (2005) the
# coefficient k_h of the joint's flat impact (N = k_h delta^1.5) is the one that stores the same
# energy at the same peak penetration as the Kelvin spring EA/L at the impact speed
# impactSpeedRef: k_h = 1.25 K / sqrt(delta*), delta* = v sqrt(m / K), m = M1 M2 / (M1 + M2) of
# two spans; shared by the 8 pairs as K is. impactSpeedRef is the case study's largest relative
# speed at impact (0.24 m/s at 1.0 times the record, 0.34 m/s at 1.5: measured on the pound case),
# also hertzdamp's v0, the speed its damping is tuned to
set impactLaw kelvin
set impactSpeedRef 0.3      ;# m/s
set frictionS 0.5
set frictionK 0.4
set contactSearch 0.5       ;# m, pairs further apart cost one bounding-sphere test
set contactInset 0.25       ;# m, contactor points sit this far inside the face edges (see below)

# Countermeasure at each joint: cable restrainers and rubber bumpers, in X and in Y, on both sides
# of the girders (the values are the totals of a joint)
set restrainerK 4.0e4       ;# kN/m (ours)
set restrainerSlack 0.05    ;# m, free opening before the cables pull (ours; well within the JRA
                            ;# limit of the devices' travel, 0.75 S_E = 0.68 m)
# Strength: the design force of unseating-prevention devices, 1.5 R_d with R_d the dead-load
# reaction of a girder end (JRA Specifications for Highway Bridges Part V, 2002, 16.3): 4409 kN
set restrainerFy [expr {1.5 * 0.5 * $girderMass * ($spanLength - $jointGap) * $g}]
set restrainerB 0.02
set bumperK 1.0e5           ;# kN/m
set bumperClearance 0.03    ;# m (< jointGap: the bumper closes before the girders touch)
set transverseSlack 0.05    ;# m, clearance of the transverse devices
set deviceArm 4.0           ;# m, devices on both sides of the girders at Y = -+deviceArm (totals above)

# Ground motion
set motionAngle 30.0        ;# degrees between the motion and the bridge axis X
set recordFile [file normalize [file join [file dirname [info script]] .. data RSN1120_KOBE_TAK090.AT2]]
# Mavroeidis-Papageorgiou pulse fitted to the Takatori EW velocity by tools/fit-pulse.tcl (least
# squares on velocity over 0-20 s; it captures the main pulse at 5-7 s, relative rms misfit 0.74
# over the whole 20 s because the record has further cycles at 2-4 s and 7-8 s)
set pulseTp 1.612; set pulseVp 1.179; set pulseGamma 1.923; set pulseNu 1.792; set pulseT0 5.762
set duration 20.0           ;# s of the record analysed
# Free vibration after the motion (the ground at rest) before the residuals are read: 6 s is about
# four isolated periods (1.6 s), over which the bearings' equivalent damping (about 15 %) leaves
# exp(-2 pi 0.15 4) = 2 % of the amplitude
set tailDuration 6.0
# Scales of the record run by the whole study (case all): three, so that the main job stays within
# two minutes (1.25 and 1.75 added 45 % to it once ruptured bearings came down onto their seats)
set ladderScales {1.0 1.5 2.0}
set viewerDt 0.05           ;# s between the frames of the viewer pages

# Serviceability after the earthquake, as traffic (the report: one verdict per case, with how the
# verdicts move when the limits that are ours change by half and by twice):
#  - unseating: a girder end must stay on its seat, i.e. move towards the cap's edge by less than
#    its seat length, here half the cap length less half the gap (1.475 m); the JRA minimum seat
#    length S_EM = 0.7 + 0.005 l (m) (JRA Specifications for Highway Bridges Part V, 2002, 16.2)
#    is 0.9 m for these spans, and the report gives the margin to both. Source: JRA;
#  - pier residual drift ratio <= 1/100 (JRA Part V 1996 and 2002: residual displacement of an RC
#    pier within h/100, beyond which piers of the Kobe earthquake were rebuilt). Source: JRA;
#  - residual vertical step at a joint <= 0.05 m. Ours: no published number for a step that
#    traffic can cross was found; 0.05 m is a step an emergency vehicle crosses at low speed;
#  - residual change of a joint's opening <= the gap (0.05 m) and residual transverse offset
#    <= 0.05 m. Ours: a finger joint made for a 0.05 m gap is taken to accommodate +- its gap
#    along and across the bridge; beyond it the fingers disengage or jam.
# The peak opening during the motion is damage to the joint, reported on its own, not a verdict.
set serviceStep 0.05              ;# m, residual vertical step (ours)
set serviceResidual $jointGap     ;# m, residual longitudinal and transverse offset (ours)
set serviceDrift 0.01             ;# residual pier drift ratio (JRA)
set seatEdge [expr {0.5 * [lindex $capSize 0] - 0.5 * $jointGap}]  ;# m, girder end to the cap's edge
set seatLengthJRA [expr {0.7 + 0.005 * $spanLength}]                ;# m, S_EM (JRA)

# Analysis defaults, chosen by tools/speed-study.tcl: the fastest run within 1 % of the reference
# (dt 0.0005 s, tol 1e-6) on every reported quantity. With the fitted bearing set (a)
# (tools/results/speed.md) that is dt 0.0025 s (0.31 %; dt 0.01 s, the former set's choice, is
# 1.95 % off on the peak transverse gap at PC2, 0.45 mm), at about twice the cost of 0.01 s
set defaultDt 0.0025
# Viaducts (more than three spans) step as the three spans do. Their largest error, over many
# more joints and bearings (596 quantities at 100 spans), against a dt 0.0005 s run of the same
# size is 0.57, 1.05, 1.10 and 1.20 % at 3, 10, 30 and 100 spans at dt 0.0025 s, and 0.74, 0.67,
# 1.12 and 1.67 % at 0.005 s: always a peak transverse gap that the impacts' timing sets, which
# halving the step does not lower below about 1 % (verification/bench/results/viaduct.md)
set viaductDt $defaultDt
set defaultTol 1.0e-4
set defaultIntegrator Newmark
set contactDt 0.0005        ;# s, longest step while a joint is closed or closing (contactStepping -maxStep)
set contactLookahead 2.0    ;# steps: sub-step when the gap would close within this many steps
set contactOvershoot 1.2    ;# a step cut at a predicted first contact ends at 1.2 x that time
# The parameters above, which buildModel reads (a script that sources this file keeps its own
# later globals out of buildModel's reach).
set parameterNames [info globals]

# ---------------------------------------------------------------------------------------------
# Model
# ---------------------------------------------------------------------------------------------
# Node numbers: pier p: P(p) + {1 ground, 2 base, 3 top of hinge, 4 mid, 5 top}, bearing
# bottoms P(p) + {11 left, 12 right} + 100k (k = 1 ... bearingsPerEnd across the width; no 100k
# with one bearing per end); girder s: G(s) + {1 .. n} along the axis, bearing tops
# G(s) + {51 start, 52 end} + 100k, face corners G(s) + {61..64 start, 71..74 end}, contactor
# points G(s) + {65..68 start, 75..78 end}, device nodes G(s) + {81 start, 82 end} + 100k
# (k = 1 on the -Y side, 2 on the +Y side). Element numbers: pier p P(p) + {1 foundation,
# 2 hinge, 3, 4}, bearings P(p) + {11, 12} + 100k (the girder end's number P(p) + {11, 12} names
# the end in the report), girder s G(s) + i, pounding (8 pairs) from C(j), devices D(j) + k for
# joint j (over pier j + 1).
# Indices up to 9 keep the short numbers of the three-span study, P = 1000p, G = 10000s,
# C = 50000 + 100j, D = 60000 + 10j; from 10 on each kind has its own range (P = 10^7 + 1000p,
# G = 2 10^7 + 1000s, C = 3 10^7 + 100j, D = 4 10^7 + 10j), so no two numbers meet at any length.
proc pierBase {p} { return [expr {$p <= 9 ? 1000 * $p : 10000000 + 1000 * $p}] }
proc girderBase {s} { return [expr {$s <= 9 ? 10000 * $s : 20000000 + 1000 * $s}] }
proc poundingBase {j} { return [expr {$j <= 9 ? 50000 + 100 * $j : 30000000 + 100 * $j}] }
proc deviceTag {j} { return [expr {$j <= 9 ? 60000 + 10 * $j : 40000000 + 10 * $j}] }

# End structures beyond the end piers (endCondition adjacent or abutment): e = 0 left, 1 right,
# each with its own range of node, element and material numbers, E(e) = 5 10^7 + 10^5 e: the
# neighbour girder's centre (or the backwall) E + 1 (its ground node E + 2), its bearing tops
# E + {51 near, 52 far} + 100k, far bearing bottoms E + 5052 + 100k on the far pier's cap E + 5000
# (its ground node E + 5001), face E + {61..68 or 71..78}, device nodes E + {81, 82} + 100k;
# elements: far bearings E + 12 + 100k (the near ones are the end pier's outer line, bearingTag),
# backfill spring E + 1, far pier E + 5, pounding from E + 1000, devices E + 2000 + k; materials
# E + 1, E + 2 (backfill or far pier) and E + 11 ... E + 16 (devices).
proc endBase {e} { return [expr {50000000 + 100000 * $e}] }
# 1 when pier p is a seat-type abutment (endCondition abutment, the end supports).
proc isAbutment {p} { return [expr {$::endCondition eq "abutment" && ($p == 1 || $p == $::nSpans + 1)}] }

proc pierX {p} { return [expr {($p - 1) * $::spanLength}] }
# Height of pier p: the list pierHeights, repeated as a pattern when it is shorter than the piers.
proc pierHeight {p} { return [lindex $::pierHeights [expr {($p - 1) % [llength $::pierHeights]}]] }
# Girder ends along the bridge, each named by its number P(p) + side: 1012 (PC1), 2011, 2012,
# ... (PC4); with one bearing per end this is the bearing's element number.
proc bearingTags {} {
  set tags {}
  for {set s 1} {$s <= $::nSpans} {incr s} { lappend tags [bearingTag $s 12] [bearingTag [expr {$s + 1}] 11] }
  return $tags
}
# End on pier p: side 11 carries the girder to its left (its end), 12 the one to its right.
proc bearingTag {p side} { return [expr {[pierBase $p] + $side}] }
# Element numbers of the bearings of girder end bt (bearingTag), from -Y to +Y.
proc endBearings {bt} {
  if {$::bearingsPerEnd == 1} { return [list $bt] }
  set tags {}
  for {set k 1} {$k <= $::bearingsPerEnd} {incr k} { lappend tags [expr {$bt + 100 * $k}] }
  return $tags
}
# Every bearing element, along the bridge.
proc bearingElements {} {
  set tags {}
  foreach bt [bearingTags] { lappend tags {*}[endBearings $bt] }
  return $tags
}
# Transverse positions Y of the bearings of a girder end (centred, girderSpacing apart).
proc bearingYs {} {
  if {$::bearingsPerEnd == 1} { return {0.0} }
  set ys {}
  for {set k 1} {$k <= $::bearingsPerEnd} {incr k} {
    lappend ys [expr {($k - 0.5 * ($::bearingsPerEnd + 1)) * $::girderSpacing}]
  }
  return $ys
}
# {pier side} of a bearing tag.
proc bearingPlace {bt} {
  for {set p 1} {$p <= $::nSpans + 1} {incr p} {
    set side [expr {$bt - [pierBase $p]}]
    if {$side == 11 || $side == 12} { return [list $p $side] }
  }
  error "bearing $bt is not a bearing of the $::nSpans-span model"
}
# Name of a bridge of nSpans spans in titles.
proc bridgeName {} {
  set words {1 One 2 Two 3 Three 4 Four 5 Five}
  return [expr {[dict exists $words $::nSpans] ? "[dict get $words $::nSpans]-span bridge" : "$::nSpans-span viaduct"}]
}
# Mass moments of inertia about X, Y, Z of a solid block of mass m and sides {a b c} along X, Y, Z.
proc blockInertia {m sides} {
  lassign $sides a b c
  return [list [expr {$m * ($b * $b + $c * $c) / 12.0}] [expr {$m * ($a * $a + $c * $c) / 12.0}] \
               [expr {$m * ($a * $a + $b * $b) / 12.0}]]
}

# Effective shear modulus Geq (MPa) and equivalent damping ratio Heq of an HDR set (Y0 [MPa] U0
# [strain] n alpha0 beta q gamma, per unit area and unit rubber thickness) at shear strain X, from
# the material's own response on the test of verification/bearing/fitted-parameters.md (the
# calibration's cyclicTest): six triangular cycles of amplitude X along one axis, 40 steps per
# quarter, on the last cycle Geq = (F(+X) - F(-X)) / 2X and Heq = dW / (2 pi Geq X^2), dW its area
# (trapezoids). Runs on a bearing of unit area and unit rubber thickness (force = stress,
# displacement = strain) in a model of its own, so call it before building the model; remembered
# per set. Returns {Geq Heq}.
proc hdrLoop {set strain {perQuarter 40}} {
  set key [list $set $strain $perQuarter]
  if {[info exists ::hdrLoops($key)]} { return $::hdrLoops($key) }
  lassign $set y0 u0 n a0 b q gm
  set path {0.0}
  set u 0.0
  set du [expr {double($strain) / $perQuarter}]
  for {set qtr 0} {$qtr < 13} {incr qtr} {
    set sign [expr {$qtr == 0 || $qtr % 2 == 0 ? 1.0 : -1.0}]
    set steps [expr {$qtr == 0 ? $perQuarter : 2 * $perQuarter}]
    for {set i 0} {$i < $steps} {incr i} {
      set u [expr {$u + $sign * $du}]
      lappend path $u
    }
  }
  wipe
  model basic -ndm 3 -ndf 6
  node 1 0.0 0.0 0.0
  node 2 0.0 0.0 0.0
  fix 1 1 1 1 1 1 1
  fix 2 0 1 0 1 1 1
  biaxialMaterial Yoshida 1 $y0 $u0 $n $a0 $b $q $gm
  element yoshidaBearing 1 1 2 1 -Tr 1.0 -Kv 1.0e6 -limits 99.0 100.0   ;# no damage messages
  timeSeries Path 1 -dt 1.0 -values $path -useLast
  pattern Plain 1 1 { sp 2 1 1.0 }
  constraints Transformation
  numberer Plain
  system BandGeneral
  test NormDispIncr 1e-12 20
  algorithm Newton
  integrator LoadControl 1.0
  analysis Static
  # the last cycle starts at the second-last quarter (+X to -X), ends at the last (-X to +X)
  set last [expr {[llength $path] - 1}]
  set work 0.0
  set fPrev 0.0
  for {set i 1} {$i <= $last} {incr i} {
    if {[analyze 1] != 0} { error "hdrLoop: the cyclic test of {$set} failed at step $i" }
    set f [lindex [eleResponse 1 basicForce] 1]
    if {$i > $last - 4 * $perQuarter} {
      set work [expr {$work + 0.5 * ($f + $fPrev) * ([lindex $path $i] - [lindex $path $i-1])}]
    }
    if {$i == $last - 2 * $perQuarter} { set fNeg $f }
    set fPrev $f
  }
  wipe
  set geq [expr {($f - $fNeg) / (2.0 * $strain)}]
  set ::hdrLoops($key) [list $geq [expr {$work / (2.0 * acos(-1.0) * $geq * $strain * $strain)}]]
  return $::hdrLoops($key)
}
proc hdrEffectiveModulus {set strain} { return [lindex [hdrLoop $set $strain] 0] }

# An HDR set whose Geq and Heq at shear strain X are stiffnessFactor and dampingFactor times those
# of `set` (a production bearing's scatter, sampled in the fragility study). The Yoshida set has no
# single damping parameter, so the damping moves with the yield deformation: U0 -> c U0 with
# gamma -> c^2 gamma and beta -> c^q beta, which leaves the hardening Y0 gamma (U/U0)^2 and the
# back-force factor alpha0 - beta (Umax/U0)^q as they were at every deformation and changes only
# how soon the rubber yields (a larger U0, a softer start: a fuller loop). Heq rises monotonically
# with c (0.10 at c = 0.5, 0.17 at 1, 0.24 at 2 for set (a) at 250 %); c is found by the secant
# method on ln Heq against ln c. The force is homogeneous of degree one in Y0 (no Maxwell part), so
# Y0 then scales Geq exactly and leaves Heq. In a model of its own, like hdrLoop.
proc hdrScaled {set stiffnessFactor dampingFactor strain} {
  lassign $set y0 u0 n a0 b q gm
  lassign [hdrLoop $set $strain] geq0 heq0
  set target [expr {log($dampingFactor * $heq0)}]
  set variant {{c} {
    upvar 1 y0 y0 u0 u0 n n a0 a0 b b q q gm gm
    return [list $y0 [expr {$c * $u0}] $n $a0 [expr {$b * pow($c, $q)}] $q [expr {$gm * $c * $c}]]
  }}
  set x0 0.0; set r0 [expr {log($heq0) - $target}]
  set x1 [expr {0.5 * log($dampingFactor)}]   ;# ln Heq rises about half as fast as ln c
  for {set it 0} {$it < 30 && abs($r0) > 1e-6} {incr it} {
    set r1 [expr {log([lindex [hdrLoop [apply $variant [expr {exp($x1)}]] $strain] 1]) - $target}]
    if {$r1 == $r0} { break }
    set x2 [expr {$x1 - $r1 * ($x1 - $x0) / ($r1 - $r0)}]
    set x0 $x1; set r0 $r1; set x1 $x2
  }
  if {abs($r0) > 1e-6} { error "hdrScaled: no yield deformation gives $dampingFactor times the damping of {$set}" }
  set scaled [apply $variant [expr {exp($x0)}]]
  set geq [lindex [hdrLoop $scaled $strain] 0]
  return [lreplace $scaled 0 0 [expr {$y0 * $stiffnessFactor * $geq0 / $geq}]]
}

# The end face of a girder (or of what faces it across a joint) at x, rigidly tied to node center:
# corners base + tagBase + {1..4}, (y, z) counter-clockwise seen from +X, and contactor points
# base + tagBase + {5..8} inset from the corners by contactInset. Two equal faces have their
# corners on each other's edges, so a corner would enter and leave the other face with every
# sub-millimetre relative movement (force jumps that stall Newton and make the peaks depend on
# round-off); inset points stay on the other face while the relative transverse and vertical
# offsets are below the inset, and all eight pairs share a flat impact (K is EA/L / 8).
proc endFace {base tagBase x center zG} {
  set hw [expr {0.5 * $::girderWidth}]; set hd [expr {0.5 * $::girderDepth}]
  set iw [expr {$hw - $::contactInset}]; set id [expr {$hd - $::contactInset}]
  set k 0
  foreach {dy dz cy cz} [list -$hw -$hd -$iw -$id $hw -$hd $iw -$id $hw $hd $iw $id -$hw $hd -$iw $id] {
    incr k
    node [expr {$base + $tagBase + $k}] $x $dy [expr {$zG + $dz}]
    rigidLink beam $center [expr {$base + $tagBase + $k}]
    node [expr {$base + $tagBase + 4 + $k}] $x $cy [expr {$zG + $cz}]
    rigidLink beam $center [expr {$base + $tagBase + 4 + $k}]
  }
}

# Pounding both ways across a joint between the end face (70s) of the body numbered from left and
# the start face (60s) of the one numbered from right, masses mL and mR; returns the pair tags
# (from tag). The left end face has outward normal +X and the right start face -X: corner order
# gives (b - a) x (d - a) pointing towards the other girder.
# The axial arguments of a bearing of rubber area `area` whose linear vertical stiffness is Kv.
proc bearingAxialArgs {area Kv} {
  switch -- $::bearingVertical {
    linear { return [list -Tr $::bearingTr -Kv $Kv] }
    kumar {
      set Do [expr {sqrt(4.0 * $area / $::pi)}]
      set n [expr {max(1, round($::bearingTr / ($Do / (4.0 * $::shapeFactor))))}]
      return [list -vertical kumar $::rubberG $::rubberKbulk 0.0 $Do $::shimThickness \
          [expr {$::bearingTr / $n}] $n -pDelta]
    }
  }
  error "bearingVertical must be linear or kumar, got \"$::bearingVertical\""
}

proc jointPounding {tag left right mL mR K} {
  set faceL [list [expr {$left + 71}] [expr {$left + 72}] [expr {$left + 73}] [expr {$left + 74}]]
  set faceR [list [expr {$right + 61}] [expr {$right + 64}] [expr {$right + 63}] [expr {$right + 62}]]
  set pointsL [list [expr {$left + 75}] [expr {$left + 76}] [expr {$left + 77}] [expr {$left + 78}]]
  set pointsR [list [expr {$right + 65}] [expr {$right + 66}] [expr {$right + 67}] [expr {$right + 68}]]
  return [pounding $tag -side1 $pointsL $faceL -side2 $pointsR $faceR {*}[impactLawArgs $K] \
      -mu_s $::frictionS -mu_k $::frictionK -masses [expr {$mL / 8.0}] [expr {$mR / 8.0}] -search $::contactSearch]
}

# The normal law's arguments of one pair with the Kelvin stiffness K (EA/L / 8, see impactLaw).
# The power laws keep K as the friction's stiffness (-Kt).
proc impactLawArgs {K} {
  if {$::impactLaw eq "kelvin"} { return [list -K $K -e $::restitution] }
  set m [expr {0.5 * $::girderMass * $::spanLength}]
  set delta [expr {$::impactSpeedRef * sqrt($m / (8.0 * $K))}]
  set kh [expr {1.25 * $K / sqrt($delta)}]
  switch -- $::impactLaw {
    hertz { return [list -law hertz -K $kh -n 1.5 -Kt $K] }
    hertzdamp { return [list -law hertzdamp -K $kh -n 1.5 -e $::restitution -v0 $::impactSpeedRef -Kt $K] }
    jankowski { return [list -law jankowski -K $kh -e $::restitution -Kt $K] }
  }
  error "impactLaw must be kelvin, hertz, hertzdamp or jankowski, got \"$::impactLaw\""
}

# The countermeasure across a joint at x = xj: devices on both sides of the girders (at
# Y = -deviceArm and +deviceArm), each with half of the stiffness and strength, so that the pair
# of longitudinal devices resists the relative rotation of the girder ends about the vertical by
# its couple (K/2) (2 deviceArm)^2 / 2. Materials matBase + 1 ... 6, device nodes left + 82 + 100k
# and right + 81 + 100k tied to leftNode and rightNode, elements eleTag + k; returns the elements.
proc jointDevices {matBase eleTag left right leftNode rightNode xj zG} {
  set m $matBase
  uniaxialMaterial Restrainer [expr {$m + 1}] [expr {0.5 * $::restrainerK}] $::restrainerSlack -Fy [expr {0.5 * $::restrainerFy}] -b $::restrainerB
  uniaxialMaterial Bumper [expr {$m + 2}] [expr {0.5 * $::bumperK}] $::bumperClearance
  uniaxialMaterial Parallel [expr {$m + 3}] [expr {$m + 1}] [expr {$m + 2}]
  uniaxialMaterial Restrainer [expr {$m + 4}] [expr {0.5 * $::restrainerK}] $::transverseSlack -Fy [expr {0.5 * $::restrainerFy}] -b $::restrainerB
  uniaxialMaterial Bumper [expr {$m + 5}] [expr {0.5 * $::bumperK}] $::transverseSlack
  uniaxialMaterial Parallel [expr {$m + 6}] [expr {$m + 4}] [expr {$m + 5}]
  set eles {}
  foreach k {1 2} y [list -$::deviceArm $::deviceArm] {
    set nL [expr {$left + 82 + 100 * $k}]; set nR [expr {$right + 81 + 100 * $k}]
    node $nL $xj $y $zG
    node $nR $xj $y $zG
    rigidLink beam $leftNode $nL
    rigidLink beam $rightNode $nR
    element zeroLength [expr {$eleTag + $k}] $nL $nR -mat [expr {$m + 3}] [expr {$m + 6}] -dir 1 2
    lappend eles [expr {$eleTag + $k}]
  }
  return $eles
}

proc buildModel {case} {
  foreach v $::parameterNames { if {$v ne "case" && ![string match tcl* $v] && ![string match auto* $v]} { global $v } }
  if {$girderElements < 1 || $girderElements > 8} { error "girderElements must be 1 ... 8, got $girderElements" }
  hdrEffectiveModulus $hdr $bearingDesignStrain   ;# its own small model: before this one
  wipe
  model basic -ndm 3 -ndf 6

  # --- derived section and foundation properties ---
  set Ag [expr {$pi * $pierD * $pierD / 4.0}]
  set Ig [expr {$pi * pow($pierD, 4) / 64.0}]
  set pierMass [expr {$concreteDensity * $Ag}]
  set Ip [expr {$pi * pow($pileD, 4) / 64.0}]
  set Ap [expr {$pi * $pileD * $pileD / 4.0}]
  set EIp [expr {$pileE * $Ip}]
  # Chang's beam on elastic foundation: beta = (k_h D / 4 EI)^(1/4); fixed-head lateral stiffness
  # of a long pile 4 EI beta^3. Axial: a Ap Ep / L with a = 0.031 L/D - 0.15 for cast-in-place
  # piles (JRA Specifications for Highway Bridges Part IV, 2002, the pile's axial spring; as we
  # read that table: check it against the code's text before a design use)
  set beta [expr {pow($subgradeKh * $pileD / (4.0 * $EIp), 0.25)}]
  set kPileH [expr {4.0 * $EIp * pow($beta, 3)}]
  set aV [expr {0.031 * $pileLength / $pileD - 0.15}]
  set kPileV [expr {$aV * $Ap * $pileE / $pileLength}]
  set kFH 0.0; set kFV 0.0; set kFR 0.0; set kFT 0.0
  foreach xi {-1 0 1} {
    foreach yi {-1 0 1} {
      set x [expr {$xi * $pileSpacing}]; set y [expr {$yi * $pileSpacing}]
      set kFH [expr {$kFH + $kPileH}]
      set kFV [expr {$kFV + $kPileV}]
      set kFR [expr {$kFR + $kPileV * $x * $x}]       ;# rocking (same about X and Y)
      set kFT [expr {$kFT + $kPileH * ($x * $x + $y * $y)}]
    }
  }
  # Bearings: Yoshida set scaled by area and rubber thickness; vertical stiffness from the
  # compression modulus Ec = 3 G (1 + 2 kappa S^2), kappa = 0.8 (Gent); roll stiffness of the
  # rubber; torsion of the bearing pair from the shear stiffness.
  lassign $hdr y0 u0 n a0 b q gm
  set Y0 [expr {$y0 * 1000.0 * $bearingArea}]
  set U0 [expr {$u0 * $bearingTr}]
  set Ec [expr {3.0 * $rubberG * (1.0 + 2.0 * 0.8 * $shapeFactor * $shapeFactor)}]
  set bearingKv [expr {$Ec * $bearingArea / $bearingTr}]
  # rocking of one girder end on its pair of bearings (-Kr Kry Krz; local y = X, local z = Y):
  # roll about the bridge axis X is carried by the two bearings' axial springs at +-arm,
  # Kv arm^2; the end's bending rotation about Y by the pads' own bending, (Ec/3) I / Tr, with
  # Ec/3 = E (1 + 2/3 kappa S^2) the bending modulus of a bonded layer (Gent) and I that of two
  # square pads of half the area each
  set bearingKroll [expr {$bearingKv * $bearingRollArm * $bearingRollArm}]
  set padSide [expr {sqrt(0.5 * $bearingArea)}]
  set bearingKbend [expr {$Ec / 3.0 * 2.0 * pow($padSide, 4) / 12.0 / $bearingTr}]
  # Effective shear stiffness of one girder end's bearings at the design strain (kN/m). Not Y0/U0:
  # with n well below 1 the tangent leaves Y0/U0 at once (fitted-parameters.md), so Y0/U0 is the
  # stiffness over a strain of about 1e-6: for set (a) 6.38 MPa, 4 to 11 times the secant Geq of
  # cycles from 10 % to 300 %.
  set bearingKeq [expr {[hdrEffectiveModulus $hdr $bearingDesignStrain] * 1000.0 * $bearingArea / $bearingTr}]
  set bearingKt [expr {$bearingKeq * $bearingRollArm * $bearingRollArm}]
  # Bearings across the width (bearingsPerEnd > 1): each a square pad of 1/n of the area, with the
  # pad's own stiffnesses; the girder end's roll and yaw come from the pads' positions. Torsion of
  # one pad: Geq J / Tr, J = a^4 / 6 the polar moment of a square of side a (small against the
  # yaw resistance of the pads' shear, Keq y^2); rocking: (Ec/3) a^4 / 12 / Tr.
  set nB $bearingsPerEnd
  set padA [expr {$bearingArea / $nB}]
  set padSideB [expr {sqrt($padA)}]
  set padKv [expr {$Ec * $padA / $bearingTr}]
  set padKt [expr {[hdrEffectiveModulus $hdr $bearingDesignStrain] * 1000.0 * pow($padSideB, 4) / 6.0 / $bearingTr}]
  set padKr [expr {$Ec / 3.0 * pow($padSideB, 4) / 12.0 / $bearingTr}]
  set spanMass [expr {$girderMass * ($spanLength - 2.0 * 0.5 * $jointGap)}]
  # Isolated period estimate (deck on its two bearings at Keq) for the foundation dashpots.
  set Tiso [expr {2.0 * $pi * sqrt($spanMass / (2.0 * $bearingKeq))}]
  set wIso [expr {2.0 * $pi / $Tiso}]
  set cF [expr {2.0 * $foundationDamping / $wIso}]
  # Damping targets: piers at their cantilever period (cap + a quarter of the pier mass on
  # 3 E Ieff / H^3), girders at their first vertical mode (pi^2/L^2 sqrt(EI/m)).
  set hMean 0.0
  for {set p 1} {$p <= $nSpans + 1} {incr p} { set hMean [expr {$hMean + [pierHeight $p] / ($nSpans + 1)}] }
  set kPier [expr {3.0 * $concreteE * $crackedFactor * $Ig / pow($hMean, 3)}]
  set wPier [expr {sqrt($kPier / ($capMass + 0.24 * $pierMass * $hMean))}]
  set wGirder [expr {$pi * $pi / ($spanLength * $spanLength) * sqrt($steelE * $girderIvert / $girderMass)}]
  set ::derived [dict create kFH $kFH kFV $kFV kFR $kFR kFT $kFT cF $cF Y0 $Y0 U0 $U0 \
      bearingKeq $bearingKeq seatK [expr {$nB == 1 ? $bearingKv : $padKv}] \
      bearingKv $bearingKv Tiso $Tiso spanMass $spanMass kPier $kPier pierMass $pierMass \
      wPier $wPier wGirder $wGirder]

  # --- materials ---
  uniaxialMaterial Concrete02 1 $fcCore -0.0025 -8000.0 -0.02 0.1 3000.0 1.5e6
  uniaxialMaterial Concrete02 2 $fcCover -0.002 -5000.0 -0.005 0.1 2500.0 1.2e6
  uniaxialMaterial Steel02 3 $steelFy 2.0e8 0.01 18.0 0.925 0.15
  set rCore [expr {$pierD / 2.0 - $pierCover}]
  section Fiber 1 -GJ [expr {$concreteG * $pi * pow($pierD, 4) / 32.0}] {
    patch circ 1 12 $coreRings 0.0 0.0 0.0 $rCore 0.0 360.0
    patch circ 2 12 1 0.0 0.0 $rCore [expr {$pierD / 2.0}] 0.0 360.0
    layer circ 3 $nBars $barArea 0.0 0.0 [expr {$rCore - 0.02}] 0.0 [expr {360.0 - 360.0 / $nBars}]
  }
  beamIntegration Lobatto 1 1 $integrationPoints
  geomTransf PDelta 1 1.0 0.0 0.0     ;# piers (vertical)
  geomTransf Linear 2 0.0 0.0 1.0     ;# girders (along X): local y = Y, local z = Z
  foreach dir {1 2 3 4 5 6} k [list $kFH $kFH $kFV $kFR $kFR $kFT] {
    uniaxialMaterial Elastic [expr {10 + $dir}] $k [expr {$cF * $k}]
  }
  # one girder end's bearings (bearingsPerEnd 1) or one pad of them
  biaxialMaterial Yoshida 1 [expr {$Y0 / $nB}] $U0 $n $a0 $b $q $gm

  # --- piers ---
  set heights {}
  for {set p 1} {$p <= $nSpans + 1} {incr p} { lappend heights [pierHeight $p] }
  set zTop [tcl::mathfunc::max {*}$heights]   ;# bearing seats; the highest footing at Z = 0
  set pierEles {}
  set ::groundNodes {}
  for {set p 1} {$p <= $nSpans + 1} {incr p} {
    set x [pierX $p]
    set b [pierBase $p]
    set H [pierHeight $p]
    set z0 [expr {$zTop - $H}]
    if {[isAbutment $p]} {
      # seat-type abutment: its bearing seat moves with the ground (no pier, no mass)
      set side [expr {$p == 1 ? 12 : 11}]
      foreach bn [endBearings [bearingTag $p $side]] y [bearingYs] {
        node $bn [expr {$x + ($p == 1 ? 1.0 : -1.0) * $bearingOffset}] $y $zTop
        fix $bn 1 1 1 1 1 1
        lappend ::groundNodes $bn
      }
      continue
    }
    lappend ::groundNodes [expr {$b + 1}]
    # Pier mass lumped at the nodes, half of each segment to its end nodes (what a lumped element
    # mass gives), so that every mass is a nodal mass: the dead load, the ground-motion input -M r
    # a_g and the energy balance (energy.tcl) then read it with nodeMass.
    set lSeg [expr {0.5 * ($H - $hingeLength)}]
    set m2 [expr {$footingMass + 0.5 * $pierMass * $hingeLength}]
    set m3 [expr {0.5 * $pierMass * ($hingeLength + $lSeg)}]
    set m4 [expr {$pierMass * $lSeg}]
    set m5 [expr {$capMass + 0.5 * $pierMass * $lSeg}]
    # rotary inertia of the footing and the cap (solid blocks), so that no rotation carrying a
    # spring and dashpot or a rigid link to heavy parts is massless
    lassign [blockInertia $footingMass $footingSize] fIx fIy fIz
    lassign [blockInertia $capMass $capSize] cIx cIy cIz
    node [expr {$b + 1}] $x 0.0 $z0
    node [expr {$b + 2}] $x 0.0 $z0 -mass $m2 $m2 $m2 $fIx $fIy $fIz
    node [expr {$b + 3}] $x 0.0 [expr {$z0 + $hingeLength}] -mass $m3 $m3 $m3 0.0 0.0 0.0
    node [expr {$b + 4}] $x 0.0 [expr {0.5 * ($z0 + $hingeLength + $zTop)}] -mass $m4 $m4 $m4 0.0 0.0 0.0
    node [expr {$b + 5}] $x 0.0 $zTop -mass $m5 $m5 $m5 $cIx $cIy $cIz
    fix [expr {$b + 1}] 1 1 1 1 1 1
    element zeroLength [expr {$b + 1}] [expr {$b + 1}] [expr {$b + 2}] -mat 11 12 13 14 15 16 -dir 1 2 3 4 5 6
    element forceBeamColumn [expr {$b + 2}] [expr {$b + 2}] [expr {$b + 3}] 1 1
    set EIeff [expr {$crackedFactor * $Ig}]
    foreach e {3 4} i {3 4} j {4 5} {
      element elasticBeamColumn [expr {$b + $e}] [expr {$b + $i}] [expr {$b + $j}] $Ag $concreteE \
          $concreteG [expr {2.0 * $EIeff}] $EIeff $EIeff 1
    }
    lappend pierEles [expr {$b + 2}] [expr {$b + 3}] [expr {$b + 4}]
    # bearing seats on the cap (rigid cap: rigid links from the pier top)
    # (the end piers' outer bearing lines carry the next units' girders with endCondition adjacent)
    set outer [expr {$endCondition eq "adjacent"}]
    foreach side {11 12} dx [list -$bearingOffset $bearingOffset] use [list [expr {$p > 1 || $outer}] [expr {$p <= $nSpans || $outer}]] {
      if {!$use} { continue }
      foreach bn [endBearings [bearingTag $p $side]] y [bearingYs] {
        node $bn [expr {$x + $dx}] $y $zTop
        rigidLink beam [expr {$b + 5}] $bn
      }
    }
  }

  # --- girders ---
  set zG [expr {$zTop + $bearingHeight + 0.5 * $girderDepth}]
  set girderEles {}
  set ::girderEndNodes {}
  for {set s 1} {$s <= $nSpans} {incr s} {
    set b [girderBase $s]
    set x0 [pierX $s]; set x1 [pierX [expr {$s + 1}]]
    # end faces: at the joints half a gap from the pier axis; at the abutment-side ends (PC1,
    # PC4) the girder ends at the same overhang
    set xs [expr {$x0 + 0.5 * $jointGap}]
    set xe [expr {$x1 - 0.5 * $jointGap}]
    set xb0 [expr {$x0 + $bearingOffset}]
    set xb1 [expr {$x1 - $bearingOffset}]
    set xs_list [list $xs]
    for {set i 0} {$i <= $girderElements} {incr i} {
      lappend xs_list [expr {$xb0 + ($xb1 - $xb0) * $i / double($girderElements)}]
    }
    lappend xs_list $xe
    set nNodes [llength $xs_list]
    # lumped mass and dead load by tributary length
    for {set i 0} {$i < $nNodes} {incr i} {
      set xl [expr {$i > 0 ? 0.5 * ([lindex $xs_list $i] + [lindex $xs_list [expr {$i - 1}]]) : [lindex $xs_list 0]}]
      set xr [expr {$i < $nNodes - 1 ? 0.5 * ([lindex $xs_list $i] + [lindex $xs_list [expr {$i + 1}]]) : [lindex $xs_list end]}]
      set m [expr {$girderMass * ($xr - $xl)}]
      # rotary inertia of the deck section (a W x D rectangle of the same mass): roll about X,
      # pitch about Y, yaw about Z (the yaw of the whole girder also comes from the masses'
      # spread along X). Without it roll is massless, and impacts at the face corners drive it
      # into the undamped period-2 oscillation that average acceleration leaves in massless
      # modes (the dashpot force then alternates from step to step)
      set Ix [expr {$m * ($girderWidth * $girderWidth + $girderDepth * $girderDepth) / 12.0}]
      set Iy [expr {$m * $girderDepth * $girderDepth / 12.0}]
      set Iz [expr {$m * $girderWidth * $girderWidth / 12.0}]
      node [expr {$b + $i + 1}] [lindex $xs_list $i] 0.0 $zG -mass $m $m $m $Ix $Iy $Iz
    }
    for {set i 1} {$i < $nNodes} {incr i} {
      element elasticBeamColumn [expr {$b + $i}] [expr {$b + $i}] [expr {$b + $i + 1}] $girderA $steelE \
          $steelG $girderJ $girderIvert $girderIlat 2
      lappend girderEles [expr {$b + $i}]
    }
    set first [expr {$b + 1}]; set last [expr {$b + $nNodes}]
    lappend ::girderEndNodes $first $last
    dict set ::girderMid $s [expr {$b + ($nNodes + 1) / 2}]
    # bearing tops, rigidly tied to the girder axis above them (the end cross beam); a ruptured
    # bearing lets its top down by bearingHeight onto its lower plate
    set drop [list -afterFailure drop $bearingHeight -seat [expr {$nB == 1 ? $bearingKv : $padKv}] {*}$seatFriction]
    foreach top {51 52} axis [list [expr {$b + 2}] [expr {$b + $nNodes - 1}]] xb [list $xb0 $xb1] \
        bt [list [bearingTag $s 12] [bearingTag [expr {$s + 1}] 11]] {
      set k [expr {$nB == 1 ? 0 : 1}]
      foreach bn [endBearings $bt] y [bearingYs] {
        set tn [expr {$b + $top + 100 * $k}]
        incr k
        node $tn $xb $y [expr {$zTop + $bearingHeight}]
        rigidLink beam $axis $tn
        if {$nB == 1} {
          element yoshidaBearing $bn $bn $tn 1 {*}[bearingAxialArgs $bearingArea $bearingKv] -Kt $bearingKt -Kr $bearingKroll $bearingKbend {*}$drop
        } else {
          element yoshidaBearing $bn $bn $tn 1 {*}[bearingAxialArgs $padA $padKv] -Kt $padKt -Kr $padKr {*}$drop
        }
      }
    }
    # end faces: corners and contactor points (endFace)
    endFace $b 60 $xs $first $zG
    endFace $b 70 $xe $last $zG
  }
  set ::pierEles $pierEles
  set ::girderEles $girderEles

  # --- expansion joints over PC2 ... PC(n): pounding and countermeasure devices ---
  set ::poundingEles {}
  set K [expr {$impactStiffnessFactor * $steelE * $girderA / $spanLength / 8.0}]
  for {set j 1} {$j < $nSpans} {incr j} {
    set left [girderBase $j]
    set right [girderBase [expr {$j + 1}]]
    set list {}
    if {$case ne "nopound"} { set list [jointPounding [poundingBase $j] $left $right $spanMass $spanMass $K] }
    lappend ::poundingEles $list
    if {$case eq "countermeasure"} {
      jointDevices [expr {100 + 10 * $j}] [deviceTag $j] $left $right \
          [lindex $::girderEndNodes [expr {2 * $j - 1}]] [lindex $::girderEndNodes [expr {2 * $j}]] [pierX [expr {$j + 1}]] $zG
    }
  }

  # --- beyond the end piers: the next units' girders or the abutments' backwalls ---
  set ::endJoints {}
  set ::endEles {}   ;# every element beyond the end piers (energy.tcl's group "ends")
  set ::deadLoadHolds {}
  if {$endCondition ne "free"} {
    foreach e {0 1} {
      set nb [endBase $e]
      set dir [expr {$e == 0 ? -1.0 : 1.0}]
      set pEnd [expr {$e == 0 ? 1 : $nSpans + 1}]
      set xe [pierX $pEnd]
      set unitEnd [expr {$e == 0 ? [lindex $::girderEndNodes 0] : [lindex $::girderEndNodes end]}]
      set unitGirder [girderBase [expr {$e == 0 ? 1 : $nSpans}]]
      set xFace [expr {$xe + $dir * 0.5 * $jointGap}]
      if {$endCondition eq "adjacent"} {
        # the neighbour girder: one node at its centre with the span's mass and rotary inertia
        set xc [expr {$xe + $dir * 0.5 * $spanLength}]
        set m $spanMass
        lassign [blockInertia $m [list $spanLength $girderWidth $girderDepth]] nIx nIy nIz
        set center [expr {$nb + 1}]
        node $center $xc 0.0 $zG -mass $m $m $m $nIx $nIy $nIz
        # its bearings: near end on the end pier's outer line, far end on the next pier, idealised
        # as its cap (mass and rotary inertia) on the cracked cantilever's lateral stiffness kPier
        # at the mean pier height (elastic: its own hinge is left out) and the pile group's
        # vertical stiffness, held in rotation
        set nearX [expr {$xe + $dir * $bearingOffset}]
        set farX [expr {$xe + $dir * ($spanLength - $bearingOffset)}]
        set farCap [expr {$nb + 5000}]; set farGround [expr {$nb + 5001}]
        set xFar [expr {$xe + $dir * $spanLength}]
        set mCap [expr {$capMass + 0.24 * $pierMass * $hMean}]
        lassign [blockInertia $capMass $capSize] cIx cIy cIz
        node $farCap $xFar 0.0 $zTop -mass $mCap $mCap $mCap $cIx $cIy $cIz
        node $farGround $xFar 0.0 $zTop
        fix $farGround 1 1 1 1 1 1
        lappend ::groundNodes $farGround
        # held along X and Y under the dead load, released for the motion (applyDeadLoad): Newton
        # does not settle the small shear that the neighbour's pitch puts on its bearings between
        # two flexible supports (the rubber's tangent varies steeply at strains near zero)
        fix $farCap 1 1 0 1 1 1
        lappend ::deadLoadHolds [list $farCap 1] [list $farCap 2]
        uniaxialMaterial Elastic [expr {$nb + 1}] $kPier
        uniaxialMaterial Elastic [expr {$nb + 2}] $kFV
        element zeroLength [expr {$nb + 5}] $farGround $farCap -mat [expr {$nb + 1}] [expr {$nb + 1}] [expr {$nb + 2}] -dir 1 2 3
        lappend ::endEles [expr {$nb + 5}]
        set k [expr {$nB == 1 ? 0 : 1}]
        foreach bn [endBearings [bearingTag $pEnd [expr {$e == 0 ? 11 : 12}]]] y [bearingYs] {
          set nearTop [expr {$nb + 51 + 100 * $k}]; set farTop [expr {$nb + 52 + 100 * $k}]
          set farBottom [expr {$nb + 5052 + 100 * $k}]; set farEle [expr {$nb + 12 + 100 * $k}]
          incr k
          node $nearTop $nearX $y [expr {$zTop + $bearingHeight}]
          node $farTop $farX $y [expr {$zTop + $bearingHeight}]
          node $farBottom $farX $y $zTop
          rigidLink beam $farCap $farBottom
          rigidLink beam $center $nearTop
          rigidLink beam $center $farTop
          foreach ele [list $bn $farEle] i [list $bn $farBottom] j [list $nearTop $farTop] {
            lappend ::endEles $ele
            if {$nB == 1} {
              element yoshidaBearing $ele $i $j 1 {*}[bearingAxialArgs $bearingArea $bearingKv] -Kt $bearingKt -Kr $bearingKroll $bearingKbend {*}$drop
            } else {
              element yoshidaBearing $ele $i $j 1 {*}[bearingAxialArgs $padA $padKv] -Kt $padKt -Kr $padKr {*}$drop
            }
          }
        }
        set other $center
        set otherMass $m
      } else {
        # the backwall: a node behind the face on a bilinear backfill spring along X (stiff in
        # the other directions), Caltrans SDC 1.7 7.8.1 with h the backwall's height
        set hBw [expr {$girderDepth + $bearingHeight}]
        set kAbut [expr {$abutmentKi * $girderWidth * $hBw / 1.7}]
        set pAbut [expr {$abutmentPressure * $girderWidth * $hBw * $hBw / 1.7}]
        set center [expr {$nb + 1}]
        node $center $xFace 0.0 $zG
        node [expr {$nb + 2}] $xFace 0.0 $zG
        fix [expr {$nb + 2}] 1 1 1 1 1 1
        lappend ::groundNodes [expr {$nb + 2}]
        uniaxialMaterial ElasticPP [expr {$nb + 1}] $kAbut [expr {$pAbut / $kAbut}]
        uniaxialMaterial Elastic [expr {$nb + 2}] [expr {100.0 * $kAbut}]
        element zeroLength [expr {$nb + 1}] [expr {$nb + 2}] $center -mat [expr {$nb + 1}] {*}[lrepeat 5 [expr {$nb + 2}]] -dir 1 2 3 4 5 6
        lappend ::endEles [expr {$nb + 1}]
        set other $center
        set otherMass 1.0e6   ;# t: the ground's side of the contact (m_eff = the girder's)
      }
      # the other side's face across the joint gap: a left neighbour's end face (70s) meets the
      # first girder's start face (60s), a right one's start face (60s) the last girder's end face
      endFace $nb [expr {$e == 0 ? 70 : 60}] $xFace $other $zG
      if {$e == 0} {
        set left $nb; set right $unitGirder; set mL $otherMass; set mR $spanMass
      } else {
        set left $unitGirder; set right $nb; set mL $spanMass; set mR $otherMass
      }
      set list {}
      if {$case ne "nopound"} {
        set list [jointPounding [expr {$nb + 1000}] $left $right $mL $mR $K]
        lappend ::endEles {*}$list
      }
      if {$case eq "countermeasure" && $endCondition eq "adjacent"} {
        lappend ::endEles {*}[jointDevices [expr {$nb + 10}] [expr {$nb + 2000}] $left $right \
            [expr {$e == 0 ? $other : $unitEnd}] [expr {$e == 0 ? $unitEnd : $other}] $xe $zG]
      }
      # {left node, right node, contact pairs, other side's node, lever, its face's corners}: the
      # end joint as a joint (gap = right - left). The other side's node is the neighbour's centre
      # (adjacent) or the backwall's node on the face (abutment); lever is the face's offset from
      # it along X, so that its face moves as u + theta x (lever, 0, 0): the neighbour's yaw and
      # pitch move its end transversely and vertically by 20 m times the rotation, which its
      # centre does not show
      set lever [expr {$xFace - [nodeCoord $other 1]}]
      set corners [lmap k {1 2 3 4} {expr {$nb + ($e == 0 ? 70 : 60) + $k}}]
      lappend ::endJoints [list [expr {$e == 0 ? $other : $unitEnd}] [expr {$e == 0 ? $unitEnd : $other}] $list \
          $other $lever $corners]
    }
  }

  # --- Rayleigh damping, stiffness-proportional on the initial stiffness, piers and girders only
  region 1 -eleOnly {*}$pierEles -rayleigh 0.0 0.0 [expr {2.0 * $pierDamping / $wPier}] 0.0
  region 2 -eleOnly {*}$girderEles -rayleigh 0.0 0.0 [expr {2.0 * $girderDamping / $wGirder}] 0.0
}

# Periods (s) of the first n modes at the dead-load state, of the bridge as built (no pounding):
#   initial    the bearings at their tangent after the dead load (small strains: stiff, n < 1)
#   effective  the bearings' shear a linear spring of their effective stiffness Keq at the design
#              strain (the equivalent linear bridge of design practice): a Yoshida law with no
#              back force and n = 20 whose yield deformation, 100 Tr, is never approached
# Builds its own models (call it between runs); returns {initial {T..} effective {T..}}.
proc modalPeriods {n} {
  global hdr
  set out {}
  set saved $hdr
  foreach kind {initial effective} {
    if {$kind eq "effective"} {
      set Geq [hdrEffectiveModulus $saved $::bearingDesignStrain]
      set hdr [list [expr {$Geq * 100.0}] 100.0 20.0 0.0 0.0 1.0 0.0]
    }
    buildModel nopound
    set rc [applyDeadLoad]
    set hdr $saved
    if {$rc != 0} { error "modalPeriods: the dead load of the $kind model failed" }
    dict set out $kind [lmap l [eigen $n] { expr {2.0 * $::pi / sqrt($l)} }]
  }
  wipe
  return $out
}

# Dead load: the weight of every nodal mass, applied in ten static steps, then held; then the
# supports held for it alone (deadLoadHolds) are released.
proc applyDeadLoad {} {
  global g
  timeSeries Linear 1
  pattern Plain 1 1 {
    foreach n [getNodeTags] {
      set w [expr {[nodeMass $n 3] * $g}]
      if {$w > 0.0} { load $n 0.0 0.0 [expr {-$w}] 0.0 0.0 0.0 }
    }
  }
  constraints Transformation
  numberer RCM
  system SparseSYM
  # On the unbalanced force, 1 kN (2e-5 of the weight): with several bearings under a girder end
  # Newton can cycle at the 1e-6 m level in the rubber's shear, where the dead load puts almost
  # none (the Yoshida law with n = 0.115 changes its tangent steeply at strains near zero), and a
  # displacement test of 1e-8 m then never passes; the cycle's unbalance is about 0.1 kN
  test NormUnbalance 1.0 30
  algorithm Newton
  integrator LoadControl 0.1
  analysis Static
  set rc [analyze 10]
  loadConst -time 0.0
  # supports held only under the dead load (buildModel's deadLoadHolds: {node dof} pairs)
  foreach hold $::deadLoadHolds { remove sp {*}$hold }
  return $rc
}

# Ground motion at $motionAngle to X: two UniformExcitation patterns (cos, sin).
proc applyMotion {motion scale} {
  global g pi motionAngle recordFile
  if {$motion eq "auto"} { set motion [expr {[file exists $recordFile] ? "record" : "pulse"}] }
  set c [expr {cos($motionAngle * $pi / 180.0)}]
  set s [expr {sin($motionAngle * $pi / 180.0)}]
  if {$motion eq "pulse"} {
    foreach tag {11 12} f [list $c $s] {
      timeSeries NearFaultPulse $tag -Tp $::pulseTp -Vp $::pulseVp -gamma $::pulseGamma \
          -nu $::pulseNu -t0 $::pulseT0 -factor [expr {$scale * $f}]
    }
    set used "Mavroeidis-Papageorgiou pulse fitted to Takatori EW (Tp $::pulseTp s, Vp $::pulseVp m/s)"
  } else {
    set file [expr {$motion eq "record" ? $recordFile : $motion}]
    foreach tag {11 12} f [list $c $s] {
      timeSeries Path $tag -filePath $file -factor [expr {$scale * $g * $f}]
    }
    set used "[file tail $file]"
  }
  pattern UniformExcitation 11 1 -accel 11
  pattern UniformExcitation 12 2 -accel 12
  return $used
}

proc setIntegrator {integrator} {
  switch -- $integrator {
    Newmark { integrator Newmark 0.5 0.25 }
    HHT { integrator HHT 0.95 }
    default { error "integrator must be Newmark or HHT, got \"$integrator\"" }
  }
}

# ---------------------------------------------------------------------------------------------
# One run: returns a dict of results; writes the time histories to $csv (if not empty). perStep,
# if given, is a command prefix evaluated once before the first step and after every converged
# step (energy.tcl follows the energy balance with it).
# ---------------------------------------------------------------------------------------------
# The quantities followed, for any number of spans: every joint (over PC2 ... PCn: peak and
# residual gaps in x, y, z, largest opening and closing, pounding force and impacts), every
# bearing (peak and residual displacements, peak shear strain, damage at the end), every girder
# (mid-span longitudinal displacement and rotation about the vertical) and the middle girder's
# deck and bearings (the histories of the three-span study: G2). Sets, in namespace run, joints,
# jointBearing (array), allBearings, midBearings, mids, midGirder, peak, last, impacts, closed
# and the CSV header columns.
namespace eval run {}
proc monitorSetup {} {
  foreach v {joints jointBearing allBearings midBearings mids midGirder peak last impacts closed columns} { variable ::run::$v }
  set nJ [expr {$::nSpans - 1}]
  set joints {}
  array unset jointBearing
  for {set j 1} {$j <= $nJ} {incr j} {
    lappend joints [list [lindex $::girderEndNodes [expr {2 * $j - 1}]] [lindex $::girderEndNodes [expr {2 * $j}]]]
    set jointBearing([bearingTag [expr {$j + 1}] 11]) 1   ;# the bearings at the joints
    set jointBearing([bearingTag [expr {$j + 1}] 12]) 1
  }
  set allBearings [bearingTags]        ;# every girder end, PC1 ... PC(n+1)
  set midGirder [expr {$::nSpans / 2 + 1}]
  set midBearings [list [bearingTag $midGirder 12] [bearingTag [expr {$midGirder + 1}] 11]]
  set mids {}
  for {set s 1} {$s <= $::nSpans} {incr s} { lappend mids [dict get $::girderMid $s] }
  set peak [dict create]
  for {set j 1} {$j <= $nJ} {incr j} { foreach d {x y z} { dict set peak gap$j$d 0.0 } }
  foreach key {open close force pen} { for {set j 1} {$j <= $nJ} {incr j} { dict set peak $key$j 0.0 } }
  for {set s 1} {$s <= $::nSpans} {incr s} { dict set peak rot$s 0.0 }
  for {set p 1} {$p <= $::nSpans + 1} {incr p} { if {![isAbutment $p]} { dict set peak drift$p 0.0 } }
  foreach e {0 1} { foreach key {endopen endclose endforce endpen} { dict set peak $key$e 0.0 }; dict set peak endimpacts$e 0 }
  set ::run::endClosed {0 0}
  dict set peak deckx 0.0; dict set peak decky 0.0
  for {set s 1} {$s <= $::nSpans} {incr s} { dict set peak g${s}x 0.0 }
  foreach bt $allBearings { dict set peak strain$bt 0.0; dict set peak bx$bt 0.0; dict set peak by$bt 0.0; dict set peak seat$bt 0.0 }
  # the direction in which a girder end leaves its seat: the start of a girder (side 12) moves +X
  # off the pier cap, its end (side 11) -X
  variable ::run::seatSign
  array unset seatSign
  foreach bt $allBearings { set seatSign($bt) [expr {[lindex [bearingPlace $bt] 1] == 12 ? 1.0 : -1.0}] }
  # each girder end's bearing elements, once per run (monitorStep reads them every step)
  variable ::run::endElements
  array unset endElements
  foreach bt $allBearings { set endElements($bt) [endBearings $bt] }
  # the piers whose drift monitorStep follows (not abutments): number, cap and footing nodes,
  # height
  variable ::run::driftPiers {}
  for {set p 1} {$p <= $::nSpans + 1} {incr p} {
    set b [pierBase $p]
    if {![isAbutment $p]} { lappend driftPiers $p [expr {$b + 5}] [expr {$b + 2}] [pierHeight $p] }
  }
  set last [dict create]
  set impacts [lrepeat $nJ 0]
  set closed [lrepeat $nJ 0]
  # CSV columns, in the order monitorStep writes them (the three-span study's columns for 3 spans)
  set columns {t}
  for {set j 1} {$j <= $nJ} {incr j} { lappend columns gap${j}x gap${j}y }
  foreach bt $allBearings { if {[info exists jointBearing($bt)]} { lappend columns strain$bt } }
  foreach bt $midBearings { lappend columns bx$bt by$bt }
  for {set j 1} {$j <= $nJ} {incr j} { lappend columns force$j }
  for {set s 1} {$s <= $::nSpans} {incr s} { lappend columns rot$s }
  lappend columns deck${midGirder}x deck${midGirder}y
  for {set s 1} {$s <= $::nSpans} {incr s} { lappend columns g${s}x }
  for {set j 1} {$j <= $nJ} {incr j} { lappend columns gap${j}z }
  foreach bt $allBearings { if {![info exists jointBearing($bt)]} { lappend columns strain$bt } }
}

# After a converged step: updates the peaks, the residuals (last), the impacts; returns the CSV row.
proc monitorStep {} {
  foreach v {joints jointBearing allBearings midBearings mids midGirder peak last impacts closed endElements seatSign} { variable ::run::$v }
  set row [list [getTime %.17g]]
  set j 0
  foreach pair $joints {
    incr j
    lassign $pair a b
    set gx [expr {[nodeDisp $b 1] - [nodeDisp $a 1]}]
    set gy [expr {[nodeDisp $b 2] - [nodeDisp $a 2]}]
    lappend row $gx $gy
    if {abs($gx) > abs([dict get $peak gap${j}x])} { dict set peak gap${j}x $gx }
    if {$gx > [dict get $peak open$j]} { dict set peak open$j $gx }    ;# largest opening
    if {$gx < [dict get $peak close$j]} { dict set peak close$j $gx }  ;# largest closing (< 0)
    if {abs($gy) > abs([dict get $peak gap${j}y])} { dict set peak gap${j}y $gy }
    dict set last gap${j}x $gx
    dict set last gap${j}y $gy
  }
  set disps {}
  set gz {}
  set j 0
  foreach pair $joints {
    incr j
    lassign $pair a b
    set z [expr {[nodeDisp $b 3] - [nodeDisp $a 3]}]
    lappend gz $z
    if {abs($z) > abs([dict get $peak gap${j}z])} { dict set peak gap${j}z $z }
    dict set last gap${j}z $z
  }
  set endStrains {}
  # (This procedure runs after every step, contact sub-steps included, so it keeps to what Tcl
  # compiles to fast code: locals rather than globals, comparisons rather than max(), a math
  # function call being several times a comparison's cost.)
  set tr $::bearingTr
  foreach bt $allBearings {
    # a girder end: the largest shear strain of its bearings (the outer ones under yaw) and the
    # mean of their displacements (the end's displacement at the girder axis)
    set e 0.0; set d1 0.0; set d2 0.0
    set ends $endElements($bt)
    foreach et $ends {
      # the element's shearStrain, |u| / Tr, from the same response (one call a bearing)
      lassign [eleResponse $et deformation] d0 u1 u2
      set strain [expr {sqrt($u1 * $u1 + $u2 * $u2) / $tr}]
      if {$strain > $e} { set e $strain }
      set d1 [expr {$d1 + $u1}]; set d2 [expr {$d2 + $u2}]
    }
    set d1 [expr {$d1 / [llength $ends]}]; set d2 [expr {$d2 / [llength $ends]}]
    if {[info exists jointBearing($bt)]} { lappend row $e } else { lappend endStrains $e }
    if {$e > [dict get $peak strain$bt]} { dict set peak strain$bt $e }
    if {abs($d1) > abs([dict get $peak bx$bt])} { dict set peak bx$bt $d1 }
    set towardsEdge [expr {$seatSign($bt) * $d1}]
    if {$towardsEdge > [dict get $peak seat$bt]} { dict set peak seat$bt $towardsEdge }
    if {abs($d2) > abs([dict get $peak by$bt])} { dict set peak by$bt $d2 }
    dict set last bx$bt $d1
    dict set last by$bt $d2
    if {$bt in $midBearings} { lappend disps $d1 $d2 }
  }
  lappend row {*}$disps
  set j 0
  foreach list $::poundingEles {
    incr j
    set f 0.0
    set deepest [dict get $peak pen$j]
    foreach e $list {
      set f [expr {$f + [lindex [eleResponse $e contactForce] 0]}]
      # penetration of the pair: a negative gap (the pairs of a joint all look along X)
      set pen [expr {-[lindex [eleResponse $e gap] 0]}]
      if {$pen > $deepest} { set deepest $pen }
    }
    dict set peak pen$j $deepest
    lappend row $f
    if {$f > [dict get $peak force$j]} { dict set peak force$j $f }
    set isClosed [expr {$f > 0.0}]
    if {$isClosed && ![lindex $closed [expr {$j - 1}]]} { lset impacts [expr {$j - 1}] [expr {[lindex $impacts [expr {$j - 1}]] + 1}] }
    lset closed [expr {$j - 1}] $isClosed
  }
  set s 0
  foreach m $mids {
    incr s
    set r [nodeDisp $m 6]
    lappend row $r
    if {abs($r) > abs([dict get $peak rot$s])} { dict set peak rot$s $r }
  }
  set dx [nodeDisp [lindex $mids [expr {$midGirder - 1}]] 1]; set dy [nodeDisp [lindex $mids [expr {$midGirder - 1}]] 2]
  lappend row $dx $dy
  set s 0
  foreach m $mids {
    incr s
    set x [nodeDisp $m 1]
    lappend row $x
    if {abs($x) > abs([dict get $peak g${s}x])} { dict set peak g${s}x $x }
  }
  lappend row {*}$gz {*}$endStrains
  # Pier drift ratio: the pier's own deformation, top minus base displacement less the base's
  # rotation times the height (the footing's rocking on its piles is not pier drift), over the
  # height H, as a magnitude over X and Y (JRA's residual-displacement limit is h/100)
  foreach {p top foot H} $::run::driftPiers {
    set pdx [expr {[nodeDisp $top 1] - [nodeDisp $foot 1] - [nodeDisp $foot 5] * $H}]
    set pdy [expr {[nodeDisp $top 2] - [nodeDisp $foot 2] + [nodeDisp $foot 4] * $H}]
    set drift [expr {hypot($pdx, $pdy) / $H}]
    if {$drift > [dict get $peak drift$p]} { dict set peak drift$p $drift }
    dict set last drift$p $drift
  }
  # The unit's end joints (endCondition adjacent or abutment): opening, closing, pounding force
  # and impacts against the next unit's girder or the backwall
  variable ::run::endClosed
  set e 0
  foreach joint $::endJoints {
    lassign $joint a b pairs
    set gx [expr {[nodeDisp $b 1] - [nodeDisp $a 1]}]
    if {$gx > [dict get $peak endopen$e]} { dict set peak endopen$e $gx }
    if {$gx < [dict get $peak endclose$e]} { dict set peak endclose$e $gx }
    dict set last endgap$e $gx
    set f 0.0
    set deepest [dict get $peak endpen$e]
    foreach c $pairs {
      set f [expr {$f + [lindex [eleResponse $c contactForce] 0]}]
      set pen [expr {-[lindex [eleResponse $c gap] 0]}]
      if {$pen > $deepest} { set deepest $pen }
    }
    dict set peak endpen$e $deepest
    if {$f > [dict get $peak endforce$e]} { dict set peak endforce$e $f }
    if {$f > 0.0 && ![lindex $endClosed $e]} { dict incr peak endimpacts$e }
    lset endClosed $e [expr {$f > 0.0}]
    incr e
  }
  if {abs($dx) > abs([dict get $peak deckx])} { dict set peak deckx $dx }
  if {abs($dy) > abs([dict get $peak decky])} { dict set peak decky $dy }
  return $row
}

# Run by the driver after every converged step (contactStepping -eachStep): follows the
# quantities, writes the CSV row at the end of each output step (run::tEnd), calls perStep.
proc run::afterStep {} {
  variable fh; variable tEnd; variable dt; variable perStep
  set row [monitorStep]
  if {$fh ne "" && $tEnd - [getTime %.17g] <= 1e-9 * $dt} { puts $fh [join $row ,] }
  if {$perStep ne ""} { uplevel #0 $perStep }
}

# Dynamic equilibrium of the whole bridge now (d'Alembert): the ground acts on the structure only
# through the foundation springs and dashpots (the reactions of the fixed ground nodes) and
# gravity through the dead load, -W along Z; their sum is the rate of change of momentum,
# sum m (u'' + a_g), with the relative accelerations u'' and the ground acceleration a_g of the
# two UniformExcitation patterns (11 along X, 12 along Y). Every other force is internal and
# cancels: girders, piers and their stiffness-proportional Rayleigh damping, bearings, contact,
# devices, rigid links. Returns the residuals {X Y Z} (reactions - W e_Z - inertia), the weight W
# and the inertia forces, kN.
proc dynamicEquilibrium {} {
  reactions -dynamic
  set ag [list [getLoadFactor 11] [getLoadFactor 12] 0.0]
  set reaction {0.0 0.0 0.0}
  foreach ground $::groundNodes {
    foreach i {0 1 2} { lset reaction $i [expr {[lindex $reaction $i] + [nodeReaction $ground [expr {$i + 1}]]}] }
  }
  set inertia {0.0 0.0 0.0}
  set W 0.0
  foreach n [getNodeTags] {
    foreach i {0 1 2} {
      set m [nodeMass $n [expr {$i + 1}]]
      if {$m != 0.0} {
        lset inertia $i [expr {[lindex $inertia $i] + $m * ([nodeAccel $n [expr {$i + 1}]] + [lindex $ag $i])}]
      }
    }
    set W [expr {$W + $::g * [nodeMass $n 3]}]
  }
  set residual {}
  foreach i {0 1 2} w [list 0.0 0.0 $W] {
    lappend residual [expr {[lindex $reaction $i] - $w - [lindex $inertia $i]}]
  }
  return [dict create residual $residual weight $W inertia $inertia]
}

proc runCase {case scale dt integrator tol motion {csv ""} {perStep ""}} {
  global duration
  set wall0 [clock microseconds]
  buildModel $case
  if {[applyDeadLoad] != 0} { error "dead load analysis failed" }
  wipeAnalysis
  set used [applyMotion $motion $scale]
  constraints Transformation
  numberer RCM
  system SparseSYM
  test NormDispIncr $tol 30
  algorithm Newton
  setIntegrator $integrator
  analysis Transient -numSubLevels 4 -numSubSteps 4

  monitorSetup
  foreach v {joints allBearings midBearings midGirder columns} { set $v [set ::run::$v] }
  set fh ""
  if {$csv ne ""} {
    # The animated page of this case: the bridge with its members' real sizes, bearings coloured
    # by shear strain, contact faces lit while closed, the joint gaps and the ground motion.
    set pads {}
    foreach bt $allBearings { lappend pads {*}[endBearings $bt] }
    set caps {}; set footings {}; set elasticPier {}
    for {set p 1} {$p <= $::nSpans + 1} {incr p} {
      if {[isAbutment $p]} { continue }
      set b [pierBase $p]
      lappend caps [expr {$b + 5}]; lappend footings [expr {$b + 2}]
      lappend elasticPier [expr {$b + 3}] [expr {$b + 4}]
    }
    set padSide [expr {sqrt($::bearingArea / $::bearingsPerEnd)}]
    set gaps {}
    set j 0
    foreach pair $joints { lappend gaps [list Gap[incr j] {*}$pair] }
    set mg G$midGirder
    recorder Viewer -file "[file rootname $csv].html" -dT $::viewerDt -title "[bridgeName]: $case" \
      -plots [list [list "girder $mg left end, longitudinal (m)" node [lindex $::girderEndNodes [expr {2 * $midGirder - 2}]] 1 disp] \
                   [list "PC[expr {$midGirder + 1}] outer bearing of $mg, shear strain" ele [lindex [endBearings [lindex $midBearings 1]] end] shearStrain 1] \
                   [list "PC$midGirder outer bearing of $mg, shear strain" ele [lindex [endBearings [lindex $midBearings 0]] end] shearStrain 1]] \
      -beamSection [list [list rect $::girderWidth $::girderDepth {*}$::girderEles] \
                         [list circle $::pierD {*}$elasticPier]] \
      -bearingPad [list [list $padSide $padSide {*}$pads]] \
      -block [list [list {*}$::capSize -dz [expr {-0.5 * [lindex $::capSize 2]}] {*}$caps] \
                   [list {*}$::footingSize -dz [expr {-0.5 * [lindex $::footingSize 2]}] {*}$footings]] \
      -gaps $gaps
    set fh [open $csv w]
    # per joint gaps x y, strains of the joint bearings, the middle girder's bearing
    # displacements, pounding force per joint, girder rotations, the middle girder's deck, girder
    # mid-span longitudinal displacements (to the ground), vertical offsets at the joints, strains
    # of the end bearings (monitorSetup)
    puts $fh [join $columns ,]
  }
  set nSteps [expr {int(round($duration / $dt))}]
  set nTail [expr {int(round($::tailDuration / $dt))}]
  set failed 0
  set loosened 0
  # Event-located contact steps by the driver: at most contactDt while a joint is closed or
  # closing, a step cut at each predicted first contact (docs/contact.md, "Contact stepping"); every
  # converged step, output step or shorter, goes through run::afterStep.
  set ::run::fh $fh; set ::run::dt $dt; set ::run::perStep $perStep; set ::run::tEnd 0.0
  contactStepping -maxStep $::contactDt -lookAhead $::contactLookahead -overshoot $::contactOvershoot \
      -eachStep run::afterStep
  set wall1 [clock microseconds]
  if {$perStep ne ""} { {*}$perStep }
  for {set step 1} {$step <= $nSteps + $nTail && !$failed} {incr step} {
    if {$step == $nSteps + 1} {
      # the end of the motion: equilibrium with the ground acceleration, then free vibration
      set equilibrium [dynamicEquilibrium]
      remove loadPattern 11
      remove loadPattern 12
    }
    set tEnd [expr {$step * $dt}]
    set ::run::tEnd $tEnd
    set remaining [expr {$tEnd - [getTime %.17g]}]
    if {$remaining <= 1e-9 * $dt} { continue }
    if {[analyze 1 $remaining] != 0} {
      # the driver already sub-stepped the failed step; try the rest of the output step with line
      # search, then Krylov-Newton, with more iterations, and last a tolerance 100 times looser
      # (contact stick-slip chattering can make Newton cycle at the 1e-4 m level); such output
      # steps are counted as "loosened"
      set rc -1
      foreach alg {NewtonLineSearch KrylovNewton Newton} t [list $tol $tol [expr {100.0 * $tol}]] {
        algorithm $alg
        test NormDispIncr $t 100
        set rc [analyze 1 [expr {$tEnd - [getTime %.17g]}]]
        if {$rc == 0} { if {$t != $tol} { incr loosened }; break }
      }
      algorithm Newton
      test NormDispIncr $tol 30
      if {$rc != 0} { incr failed }
    }
  }
  # (a run that failed in the free vibration has it from the end of the motion: the ground's
  # patterns are gone by then)
  if {![info exists equilibrium]} { set equilibrium [dynamicEquilibrium] }
  set contactSubsteps [dict get [contactStepping] contactSteps]
  contactStepping -off
  foreach v {peak last impacts} { set $v [set ::run::$v] }
  # The end joints' residual transverse and vertical offsets (read once, at the end), at the other
  # side's face: u_y + theta_z lever and u_z - theta_y lever of its node, less the unit's end node
  # (on its face), as gap = right - left. The face's position is checked against the mean of its
  # four corners, which the solver ties rigidly to its node (endFaces, checks.tcl).
  set endFaces {}
  set e 0
  foreach joint $::endJoints {
    lassign $joint a b pairs other lever corners
    set unitEnd [expr {$other == $a ? $b : $a}]
    set sign [expr {$other == $b ? 1.0 : -1.0}]
    foreach dof {2 3} rot {6 5} turn {1.0 -1.0} dir {y z} {
      set face [expr {[nodeDisp $other $dof] + $turn * [nodeDisp $other $rot] * $lever}]
      dict set last endgap$e$dir [expr {$sign * ($face - [nodeDisp $unitEnd $dof])}]
      set mean [expr {[tcl::mathop::+ {*}[lmap c $corners {nodeDisp $c $dof}]] / 4.0}]
      lappend endFaces [list [expr {$dir eq "y" ? "transverse" : "vertical"}] $face $mean]
    }
    incr e
  }
  set wall2 [clock microseconds]
  if {$fh ne ""} { close $fh }
  set damage {}
  # per girder end: the worst damage state of its bearings, how many of them failed, and of those
  # how many dropped onto their seats (with the largest seat gap: < 0 resting on the seat)
  foreach bt $allBearings {
    set worst 0; set nFailed 0; set nDropped 0; set seatGaps {}
    foreach et [endBearings $bt] {
      set d [eleResponse $et damage]
      set worst [expr {max($worst, $d)}]
      if {$d >= 2} { incr nFailed }
      if {[eleResponse $et dropped] == 1} {
        incr nDropped
        lappend seatGaps [eleResponse $et seatGap]
      }
    }
    dict set peak damage$bt $worst
    dict set peak failed$bt $nFailed
    dict set peak dropped$bt $nDropped
    if {[llength $seatGaps] > 0} {
      dict set peak seatGap$bt [tcl::mathfunc::max {*}$seatGaps]
      dict set peak seatLow$bt [tcl::mathfunc::min {*}$seatGaps]
    }
  }
  set stats [analysisStatistics]
  set dofs [expr {6 * [llength [getNodeTags]]}]
  return [dict create case $case scale $scale dt $dt integrator $integrator tol $tol motion $used \
      completed [expr {$failed == 0}] loosened $loosened equilibrium $equilibrium contactSubsteps $contactSubsteps peak $peak last $last impacts $impacts stats $stats \
      endFaces $endFaces \
      nodes [llength [getNodeTags]] elements [llength [getEleTags]] \
      wall [expr {($wall2 - $wall0) * 1e-6}] wallSteps [expr {($wall2 - $wall1) * 1e-6}] \
      endTime [getTime %.17g]]
}

# ---------------------------------------------------------------------------------------------
# Main: run when this file is the script given to dabs (not when sourced by another script).
# ---------------------------------------------------------------------------------------------
if {[info exists ::bridgeLibraryOnly]} { return }

if {$argc > 7} {
  set nSpans [lindex $argv 7]
  if {![string is integer -strict $nSpans] || $nSpans < 1} { error "nSpans must be a positive integer, got \"$nSpans\"" }
}
set case       [expr {$argc > 0 ? [lindex $argv 0] : "all"}]
set scale      [expr {$argc > 1 ? [lindex $argv 1] : 1.0}]
set dt         [expr {$argc > 2 ? [lindex $argv 2] : ($nSpans > 3 ? $viaductDt : $defaultDt)}]
set integrator [expr {$argc > 3 ? [lindex $argv 3] : $defaultIntegrator}]
set tol        [expr {$argc > 4 ? [lindex $argv 4] : $defaultTol}]
set motion     [expr {$argc > 5 ? [lindex $argv 5] : "auto"}]
set outDir     [expr {$argc > 6 ? [lindex $argv 6] : "bridge-out"}]
file mkdir $outDir
set cases [expr {$case eq "all" ? {nopound pound countermeasure} : [list $case]}]
# Runs one case and prints its statistics; csv "" writes no histories and no page.
proc runAndPrint {c scale dt integrator tol motion csv} {
  set r [runCase $c $scale $dt $integrator $tol $motion $csv]
  set st [dict get $r stats]
  puts [format "%-15s %-6s x%-4s wall %.2f s, %d equations, %d steps (%d in contact sub-steps), %d failed, %d sub-stepped, %d iterations, %d factorizations" \
      $c [lindex [dict get $r motion] 0] $scale [dict get $r wall] [dict get $st equations] [dict get $st steps] [dict get $r contactSubsteps] \
      [dict get $st failedSteps] [dict get $st subSteppedSteps] [dict get $st iterations] [dict get $st factorizations]]
  return $r
}
set results {}
foreach c $cases {
  lappend results [runAndPrint $c $scale $dt $integrator $tol $motion [file join $outDir $c.csv]]
}
# The whole study (case all with the default motion): the three cases under the other motion too
# (the built-in pulse when the record is used, and the other way round when the record is there),
# and a ladder of scales of the record for the no-pounding and pounding cases, which shows at
# which shaking bearings fail and whether pounding then reduces the displacement.
set other {}
set ladder {}
if {$case eq "all" && $motion eq "auto"} {
  set primary [expr {[file exists $recordFile] ? "record" : "pulse"}]
  set second [expr {$primary eq "record" ? "pulse" : ""}]
  if {$second ne ""} {
    foreach c $cases {
      lappend other [runAndPrint $c $scale $dt $integrator $tol $second [file join $outDir $second-$c.csv]]
    }
  }
  foreach s $ladderScales {
    foreach c {nopound pound} {
      set r [expr {$s == $scale ? [lindex $results [lsearch $cases $c]] : [runAndPrint $c $s $dt $integrator $tol $primary ""]}]
      lappend ladder [dict create scale $s case $c peak [dict get $r peak] last [dict get $r last] completed [dict get $r completed] \
          loosened [dict get $r loosened] equilibrium [dict get $r equilibrium] motion [dict get $r motion] \
          endTime [dict get $r endTime]]
    }
  }
}
source [file join [file dirname [info script]] tools findings.tcl]
source [file join [file dirname [info script]] tools report.tcl]
writeReport $results $outDir $other $ladder
puts "report: [file join $outDir report.md]"
source [file join [file dirname [info script]] .. lib check.tcl]
source [file join [file dirname [info script]] tools checks.tcl]
checks::all $results $other $ladder [expr {$case eq "all" && $scale >= 1.0}]
finish
