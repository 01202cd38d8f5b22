# SPDX-License-Identifier: MIT
# Comparison of a CSV written by one of the inputs in verification/opensees (columns case,
# quantity, value) with the CSV OpenSees 3.8.0 wrote for the same input.
#
#   compareOpenSeesCsv mine.csv reference.csv relTol absTol
# checks that both have the same rows and that every value agrees to relTol relative or absTol
# absolute (round-off of quantities that are zero); returns a dict "case,quantity" -> our value.
proc compareOpenSeesCsv {ours theirs relTol absTol} {
  set read {apply {{path} {
    set f [open $path]
    gets $f
    set rows {}
    while {[gets $f line] >= 0} {
      if {$line ne ""} { lassign [split $line ,] c q v; lappend rows "$c,$q" $v }
    }
    close $f
    return $rows
  }}}
  set mine [{*}$read $ours]
  set ref [{*}$read $theirs]
  checkTrue "[file tail $ours]: same rows as OpenSees ([expr {[llength $mine]/2}] vs [expr {[llength $ref]/2}])" \
      [expr {[dict keys $mine] eq [dict keys $ref]}]
  set worst 0.0; set worstKey ""
  dict for {key expected} $ref {
    if {![dict exists $mine $key]} continue
    set err [expr {abs([dict get $mine $key] - $expected) / max($absTol, $relTol * abs($expected))}]
    if {$err > $worst} { set worst $err; set worstKey $key }
  }
  checkTrue "[file tail $ours]: every value within $relTol relative or $absTol absolute of OpenSees 3.8.0 (worst: $worstKey at [format %.3g $worst] of the tolerance)" [expr {$worst <= 1.0}]
  return $mine
}
