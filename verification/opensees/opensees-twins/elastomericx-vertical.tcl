# SPDX-License-Identifier: MIT
# OpenSees twin of ../elastomericx-vertical.tcl: the same bearing as an ElastomericX element with
# its vertical options on (cavitation, buckling, vertical stiffness with shear; the horizontal
# stiffness variation off), local x along global Z and y along global X as in the dabs twin.
# Run by make-reference.sh (it prefers this twin to the dabs input of the same name).
proc makeBearing {tag iNode jNode} {
  global G Kbulk Di Do ts tr nLayers kc phi ac
  # qd alpha Gr Kbulk D1 D2 ts tr n x y kc PhiM ac sDratio m cd tc tag1 tag2 tag3 tag4
  element ElastomericX $tag $iNode $jNode 100.0 0.1 $G $Kbulk $Di $Do $ts $tr $nLayers \
    0.0 0.0 1.0 1.0 0.0 0.0 $kc $phi $ac 0.5 0.0 0.0 0.0 1 1 0 1
}
source [file join [file dirname [info script]] .. elastomericx-vertical-body.tcl]
