# Compatibility input: `uniaxialMaterial Fatigue` wrapping Steel02, ElasticPP and ENT, driven
# through growing strain cycles (some with a small inner cycle at each peak) until the material
# fails: with the default and with given Coffin-Manson parameters and Dmax, by a strain limit
# (-max), between peaks (tension) and at a counted peak (ENT: never in tension). Each row: strain,
# stress and tangent (units MPa); each strain is committed before the next. A failed material
# keeps 1e-8 of its stress and initial tangent, so the rows after failure (stress and a nonzero
# tangent both below 1e-6 of the wrapped material's scale) form a block of their own, compared at
# their own scale; the first 100 of them are kept.
# OpenSees 3.8's Tcl interpreter tests materials with `model testUniaxial` and uniaxialTest/
# strainUniaxialTest/stressUniaxialTest/tangUniaxialTest; dabs with testUniaxialMaterial/setStrain/
# getStress/getTangent.
wipe
set tester [llength [info commands testUniaxialMaterial]]
if {$tester} { model basic -ndm 1 -ndf 1 } else { model testUniaxial }
uniaxialMaterial Steel02 1 350.0 200000.0 0.01 18.0 0.925 0.15
uniaxialMaterial ElasticPP 2 200000.0 0.002
uniaxialMaterial ENT 3 200000.0
uniaxialMaterial Fatigue 11 1
uniaxialMaterial Fatigue 12 1 -E0 0.08 -m -0.5
uniaxialMaterial Fatigue 13 2 -E0 0.12 -m -0.4
uniaxialMaterial Fatigue 14 2 -min -0.05 -max 0.025
uniaxialMaterial Fatigue 15 1 -E0 0.1 -Dmax 0.8
# No tension: never fails between peaks (that needs a tensile stress), only at a counted peak.
uniaxialMaterial Fatigue 16 3 -E0 0.1

# Peaks of cycles growing by `step` per cycle; with `inner`, each peak is followed by a small
# reversal (back 30 % of the amplitude, forward 20 %) before the strain heads for the other side.
proc peaks {step count inner} {
  set out {}
  for {set k 1} {$k <= $count} {incr k} {
    set a [expr {$step*$k}]
    foreach s {1 -1} {
      lappend out [expr {$s*$a}]
      if {$inner} { lappend out [expr {$s*0.7*$a}] [expr {$s*0.9*$a}] }
    }
  }
  return $out
}
# The same peaks with the opposite sign (the first excursion in compression).
proc mirrored {peaks} { lmap p $peaks {expr {-$p}} }
# Strains from 0 through the peaks in increments no larger than `de`.
proc history {peaks de} {
  set out {}
  set prev 0.0
  foreach p $peaks {
    set n [expr {max(1, int(ceil(abs($p - $prev)/$de)))}]
    for {set i 1} {$i <= $n} {incr i} { lappend out [expr {$prev + ($p - $prev)*$i/double($n)}] }
    set prev $p
  }
  return $out
}

set out [open compat-fatigue.out w]
foreach {tag peaks scaleS scaleE} [list \
    11 [peaks 0.01 12 1] 350.0 200000.0 \
    12 [peaks 0.004 12 0] 350.0 200000.0 \
    13 [peaks 0.004 12 1] 400.0 200000.0 \
    14 [peaks 0.004 12 0] 400.0 200000.0 \
    15 [mirrored [peaks 0.006 12 1]] 350.0 200000.0 \
    16 [peaks 0.006 12 1] 400.0 200000.0] {
  if {$tester} { testUniaxialMaterial $tag } else { uniaxialTest $tag }
  puts $out "material $tag: strain stress tangent"
  set failed 0
  foreach e [history $peaks 0.001] {
    # 100 rows after failure show what a failed material returns.
    if {$failed && [incr failed] > 100} break
    if {$tester} {
      setStrain $e
      set s [getStress]; set t [getTangent]
    } else {
      strainUniaxialTest $e
      set s [stressUniaxialTest]; set t [tangUniaxialTest]
    }
    if {!$failed && abs($s) < 1e-6*$scaleS && abs($t) < 1e-6*$scaleE && $t != 0.0} {
      set failed 1
      puts $out "material $tag after failure: strain stress tangent"
    }
    puts $out [format "%.10g %.10g %.10g" $e $s $t]
  }
}
close $out
