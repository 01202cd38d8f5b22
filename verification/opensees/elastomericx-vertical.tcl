# SPDX-License-Identifier: MIT
# dabs twin of opensees-twins/elastomericx-vertical.tcl: the bearing is a yoshidaBearing with
# the Kumar vertical law (-vertical kumar, the arguments of ElastomericX); the shear law (a
# Yoshida material) differs from ElastomericX's and is not compared; -pDelta adds the end
# moments ElastomericX always adds. Run by
# `dabs compare.tcl elastomericx-vertical.tcl 1e-5` (ctest verify.opensees.elastomericx-vertical).
proc makeBearing {tag iNode jNode} {
  global G Kbulk Di Do ts tr nLayers kc phi ac
  biaxialMaterial Yoshida $tag 100.0 0.02 2.0 0.0 0.0 1.0 0.0
  element yoshidaBearing $tag $iNode $jNode $tag -vertical kumar $G $Kbulk $Di $Do $ts $tr \
    $nLayers -kc $kc -phi $phi -ac $ac -Kt 100.0 -Kr 100.0 -limits 4.0 4.0 -pDelta
}
source [file join [file dirname [info script]] elastomericx-vertical-body.tcl]
