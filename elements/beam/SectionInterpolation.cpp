// SPDX-License-Identifier: MIT
#include "elements/beam/SectionInterpolation.h"

#include <string>

#include "materials/InputError.h"

namespace dabs::elements {

using materials::section::SectionCode;

template <int Nb>
SectionBasicMatrix<Nb> forceInterpolation(std::span<const SectionCode> codes, double xi,
                                          double length) {
  SectionBasicMatrix<Nb> b = SectionBasicMatrix<Nb>::Zero(static_cast<int>(codes.size()), Nb);
  for (int r = 0; r < static_cast<int>(codes.size()); ++r) {
    const SectionCode c = codes[r];
    if (c == SectionCode::P) {
      b(r, 0) = 1.0;
    } else if (c == SectionCode::Mz) {
      b(r, 1) = xi - 1.0;
      b(r, 2) = xi;
    } else if (c == SectionCode::Vy) {
      b(r, 1) = b(r, 2) = 1.0 / length;
    } else if (Nb == 6 && c == SectionCode::My) {
      b(r, 3) = xi - 1.0;
      b(r, 4) = xi;
    } else if (Nb == 6 && c == SectionCode::Vz) {
      b(r, 3) = b(r, 4) = 1.0 / length;
    } else if (Nb == 6 && c == SectionCode::T) {
      b(r, 5) = 1.0;
    } else {
      throw InputError("section", "resultant code " + std::to_string(int(c)) +
                                      " is not available in a " + (Nb == 3 ? "2D" : "3D") +
                                      " beam-column");
    }
  }
  return b;
}

template <int Nb>
SectionBasicMatrix<Nb> deformationInterpolation(std::span<const SectionCode> codes, double xi,
                                                double length) {
  SectionBasicMatrix<Nb> b = SectionBasicMatrix<Nb>::Zero(static_cast<int>(codes.size()), Nb);
  const double r = 1.0 / length;
  for (int k = 0; k < static_cast<int>(codes.size()); ++k) {
    const SectionCode c = codes[k];
    if (c == SectionCode::P) {
      b(k, 0) = r;
    } else if (c == SectionCode::Mz) {
      b(k, 1) = r * (6.0 * xi - 4.0);
      b(k, 2) = r * (6.0 * xi - 2.0);
    } else if (Nb == 6 && c == SectionCode::My) {
      b(k, 3) = r * (6.0 * xi - 4.0);
      b(k, 4) = r * (6.0 * xi - 2.0);
    } else if (Nb == 6 && c == SectionCode::T) {
      b(k, 5) = r;
    } else {
      throw InputError("section", "resultant code " + std::to_string(int(c)) +
                                      " is not available in a displacement-based " +
                                      (Nb == 3 ? "2D" : "3D") + " beam-column");
    }
  }
  return b;
}

template SectionBasicMatrix<3> forceInterpolation<3>(std::span<const SectionCode>, double, double);
template SectionBasicMatrix<6> forceInterpolation<6>(std::span<const SectionCode>, double, double);
template SectionBasicMatrix<3> deformationInterpolation<3>(std::span<const SectionCode>, double,
                                                           double);
template SectionBasicMatrix<6> deformationInterpolation<6>(std::span<const SectionCode>, double,
                                                           double);

}  // namespace dabs::elements
