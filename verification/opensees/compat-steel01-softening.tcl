# Compatibility input: `uniaxialMaterial Steel01` with a negative hardening ratio (softening after
# yield), alone and with isotropic hardening parameters, along a cyclic strain history with
# reversals beyond yield. Each row: strain, stress and tangent of both materials (units MPa).
# OpenSees 3.8's Tcl interpreter tests materials with `model testUniaxial` and uniaxialTest/
# strainUniaxialTest/stressUniaxialTest/tangUniaxialTest; dabs with testUniaxialMaterial/setStrain/
# getStress/getTangent. Both commit each strain before the next.
wipe
set tester [llength [info commands testUniaxialMaterial]]
if {$tester} { model basic -ndm 1 -ndf 1 } else { model testUniaxial }
uniaxialMaterial Steel01 1 350.0 200000.0 -0.03
uniaxialMaterial Steel01 2 350.0 200000.0 -0.01 0.05 2.0 0.05 2.0
set path {0.0 0.004 0.001 -0.003 0.0055 -0.006 0.002}
set out [open compat-steel01-softening.out w]
puts $out "strain stress1 tangent1 stress2 tangent2"
set rows {}
foreach tag {1 2} {
  if {$tester} { testUniaxialMaterial $tag } else { uniaxialTest $tag }
  set prev [lindex $path 0]
  foreach target [lrange $path 1 end] {
    for {set i 1} {$i <= 25} {incr i} {
      set e [expr {$prev + ($target - $prev)*$i/25.0}]
      if {$tester} {
        setStrain $e
        lappend result($tag) [list $e [getStress] [getTangent]]
      } else {
        strainUniaxialTest $e
        lappend result($tag) [list $e [stressUniaxialTest] [tangUniaxialTest]]
      }
    }
    set prev $target
  }
}
foreach a $result(1) b $result(2) {
  puts $out [format "%.10g %.10g %.10g %.10g %.10g" {*}$a {*}[lrange $b 1 2]]
}
close $out
