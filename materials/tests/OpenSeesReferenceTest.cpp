// SPDX-License-Identifier: MIT
// Every point of the OpenSees 3.8.0 reference histories in
// verification/opensees/*.csv (made by materials.tcl there): strain, stress and tangent
// after each committed strain. The strain history is rebuilt here exactly as materials.tcl builds
// it (segments of 40 points, prev + (target - prev)*i/40.0, times a scale), and the CSV strain
// column is checked against it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "materials/Concrete01.h"
#include "materials/Concrete02.h"
#include "materials/ElasticPPGap.h"
#include "materials/Steel01.h"
#include "materials/Steel02.h"

namespace dabs::materials {
namespace {

/// The CSVs are printed with %.10g: a value is known to 5e-10 relative; allow twice that plus
/// round-off of the arithmetic.
constexpr double kRelTol = 1e-9;
/// Absolute floor, as a fraction of the material's stress (or modulus) scale, for values that
/// pass through zero (where %.10g still keeps 10 digits but our round-off does not).
constexpr double kAbsTolFraction = 1e-10;

struct Row {
  double strain, stress, tangent;
};

std::vector<Row> readCsv(const std::string& name) {
  const std::string path = std::string(DABS_OPENSEES_DIR) + "/" + name;
  std::ifstream in(path);
  std::vector<Row> rows;
  if (!in) {
    ADD_FAILURE() << "cannot open " << path;
    return rows;
  }
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream ss(line);
    Row r{};
    char c1 = 0, c2 = 0;
    ss >> r.strain >> c1 >> r.stress >> c2 >> r.tangent;
    if (!ss || c1 != ',' || c2 != ',') {
      ADD_FAILURE() << "bad line in " << name << ": " << line;
      continue;
    }
    rows.push_back(r);
  }
  return rows;
}

/// The `history` proc of materials.tcl.
std::vector<double> history(double scale) {
  const double path[] = {0.0,   0.002, -0.001, 0.004,  0.001,  -0.004, 0.006,
                         0.003, 0.008, -0.008, -0.005, -0.010, 0.012,  0.0};
  std::vector<double> out;
  double prev = path[0];
  for (std::size_t k = 1; k < std::size(path); ++k) {
    const double target = path[k];
    for (int i = 1; i <= 40; ++i) out.push_back((prev + (target - prev) * i / 40.0) * scale);
    prev = target;
  }
  return out;
}

void checkAgainstReference(UniaxialMaterial& m, const std::string& csv, double scale,
                           double stressScale, double modulusScale) {
  const auto rows = readCsv(csv);
  const auto strains = history(scale);
  ASSERT_EQ(rows.size(), strains.size()) << csv;
  int failures = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Row& r = rows[k];
    ASSERT_NEAR(strains[k], r.strain, kRelTol * std::fabs(r.strain) + 1e-15) << csv << " row " << k;
    ASSERT_TRUE(ok(m.setTrialStrain(strains[k])));
    m.commitState();
    const double tolS = kRelTol * std::fabs(r.stress) + kAbsTolFraction * stressScale;
    const double tolT = kRelTol * std::fabs(r.tangent) + kAbsTolFraction * modulusScale;
    const bool good = std::fabs(m.getStress() - r.stress) <= tolS &&
                      std::fabs(m.getTangent() - r.tangent) <= tolT;
    if (!good && ++failures <= 5) {
      ADD_FAILURE() << csv << " row " << k + 2 << " strain " << strains[k] << ": stress "
                    << m.getStress() << " vs " << r.stress << ", tangent " << m.getTangent()
                    << " vs " << r.tangent;
    }
  }
  EXPECT_EQ(failures, 0) << csv << ": points off the reference";
}

TEST(OpenSeesReferenceTest, Steel01) {
  Steel01 m(1, Steel01::Params{400.0, 2.0e5, 0.01});
  checkAgainstReference(m, "steel01.csv", 1.0, 400.0, 2.0e5);
}

TEST(OpenSeesReferenceTest, Steel02) {
  Steel02::Params p{400.0, 2.0e5, 0.01};
  p.R0 = 18.0;
  p.cR1 = 0.925;
  p.cR2 = 0.15;
  Steel02 m(2, p);
  checkAgainstReference(m, "steel02.csv", 1.0, 400.0, 2.0e5);
}

TEST(OpenSeesReferenceTest, Steel02IsotropicHardening) {
  Steel02::Params p{400.0, 2.0e5, 0.01};
  p.R0 = 18.0;
  p.cR1 = 0.925;
  p.cR2 = 0.15;
  p.a1 = 0.02;
  p.a2 = 1.0;
  p.a3 = 0.02;
  p.a4 = 1.0;
  Steel02 m(3, p);
  checkAgainstReference(m, "steel02-isohard.csv", 1.0, 400.0, 2.0e5);
}

TEST(OpenSeesReferenceTest, Concrete01) {
  Concrete01 m(4, Concrete01::Params{-30.0, -0.002, -6.0, -0.006});
  checkAgainstReference(m, "concrete01.csv", 0.5, 30.0, 30000.0);
}

TEST(OpenSeesReferenceTest, Concrete02) {
  Concrete02 m(5, Concrete02::Params{-30.0, -0.002, -6.0, -0.006, 0.1, 3.0, 1500.0});
  checkAgainstReference(m, "concrete02.csv", 0.5, 30.0, 30000.0);
}

TEST(OpenSeesReferenceTest, ElasticPPGapCompression) {
  ElasticPPGap m(6, ElasticPPGap::Params{1000.0, -50.0, -0.001, 0.0, false});
  checkAgainstReference(m, "eppgap-compression.csv", 1.0, 50.0, 1000.0);
}

TEST(OpenSeesReferenceTest, ElasticPPGapTensionDamage) {
  ElasticPPGap m(7, ElasticPPGap::Params{1000.0, 5.0, 0.002, 0.0, true});
  checkAgainstReference(m, "eppgap-tension-damage.csv", 1.0, 5.0, 1000.0);
}

}  // namespace
}  // namespace dabs::materials
