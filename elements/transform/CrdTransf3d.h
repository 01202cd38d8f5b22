// SPDX-License-Identifier: MIT
#pragma once

#include "elements/transform/CrdTransfNd.h"

namespace dabs::elements {

/// Spatial beam-column transformation (ndm 3, ndf 6). Global end displacements are ordered
/// [ux uy uz rx ry rz]_i [ux uy uz rx ry rz]_j. Local axes follow OpenSees
/// (OpenSees/OpenSees:SRC/coordTransformation/LinearCrdTransf3d.cpp computeElemtLengthAndOrient):
/// x from node i to node j, y = vecxz x x (normalised), z = x x y, so vecxz lies in the local x-z
/// plane. Basic deformations are [elongation, theta_z_i, theta_z_j, theta_y_i, theta_y_j, twist]
/// and basic forces q = [N, Mz_i, Mz_j, My_i, My_j, T].
using CrdTransf3d = CrdTransfNd<3>;

}  // namespace dabs::elements
