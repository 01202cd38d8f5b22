// SPDX-License-Identifier: MIT
#pragma once

#include "elements/transform/CrdTransfNd.h"

namespace dabs::elements {

/// Planar beam-column transformation (ndm 2, ndf 3). Global end displacements are ordered
/// [ux_i uy_i rz_i ux_j uy_j rz_j]; local axes x from node i to node j, y = Z x x; basic
/// deformations are [axial elongation, rotation at i, rotation at j] relative to the chord, and
/// basic forces q = [N, M_i, M_j] (tension and counter-clockwise end moments positive), as
/// OpenSees/OpenSees:SRC/coordTransformation/LinearCrdTransf2d.cpp.
using CrdTransf2d = CrdTransfNd<2>;

}  // namespace dabs::elements
