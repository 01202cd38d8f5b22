// SPDX-License-Identifier: MIT
#include "materials/section/geometry/QuadPatch.h"

#include "materials/InputError.h"
#include "materials/section/geometry/Polygon.h"

namespace dabs::materials::section {

QuadPatch QuadPatch::rect(int mat, int nY, int nZ, double yI, double zI, double yJ, double zJ) {
  QuadPatch p;
  p.materialTag = mat;
  p.divIJ = nY;
  p.divJK = nZ;
  p.y = {yI, yJ, yJ, yI};
  p.z = {zI, zI, zJ, zJ};
  return p;
}

void QuadPatch::validate() const {
  if (divIJ < 1) throw InputError("nIJ", "must be at least 1");
  if (divJK < 1) throw InputError("nJK", "must be at least 1");
  if (!(quadArea(y, z) > 0.0))
    throw InputError("vertices", "must enclose a positive area, listed counter-clockwise");
}

void QuadPatch::discretize(FiberList& out) const {
  // Bilinear map from (s, t) in [0,1]^2 to the quadrilateral I(0,0) J(1,0) K(1,1) L(0,1).
  auto map = [&](double s, double t, double& yy, double& zz) {
    const double n[4] = {(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t};
    yy = zz = 0.0;
    for (int a = 0; a < 4; ++a) {
      yy += n[a] * y[a];
      zz += n[a] * z[a];
    }
  };
  for (int j = 0; j < divJK; ++j) {
    for (int i = 0; i < divIJ; ++i) {
      std::array<double, 4> cy{}, cz{};
      const double s0 = double(i) / divIJ, s1 = double(i + 1) / divIJ;
      const double t0 = double(j) / divJK, t1 = double(j + 1) / divJK;
      map(s0, t0, cy[0], cz[0]);
      map(s1, t0, cy[1], cz[1]);
      map(s1, t1, cy[2], cz[2]);
      map(s0, t1, cy[3], cz[3]);
      FiberPoint f = quadCentroid(cy, cz);
      f.materialTag = materialTag;
      out.push_back(f);
    }
  }
}

}  // namespace dabs::materials::section
