// SPDX-License-Identifier: MIT
// Runs the material contract (MaterialContract.h) for every uniaxial material of this folder.

#include "materials/tests/MaterialContract.h"

#include "materials/Concrete01.h"
#include "materials/Concrete02.h"
#include "materials/ENT.h"
#include "materials/Elastic.h"
#include "materials/ElasticPP.h"
#include "materials/ElasticPPGap.h"
#include "materials/Parallel.h"
#include "materials/Series.h"
#include "materials/Steel01.h"
#include "materials/Steel02.h"
#include "materials/Viscous.h"

namespace dabs::materials::testing {
namespace {

struct ElasticCase {
  static std::unique_ptr<UniaxialMaterial> make() {
    return std::make_unique<Elastic>(1, Elastic::Params{2.0e5, 1.0e3, 1.0e5});
  }
  static double strainScale() { return 0.002; }
  static std::vector<double> path() { return cyclicPath(strainScale()); }
  static constexpr bool kRateDependent = true;
};

// Without a dashpot: rate-independent, and so kept at the same strain (ElasticCase's path).
struct ElasticNoDampingCase : ElasticCase {
  static std::unique_ptr<UniaxialMaterial> make() {
    return std::make_unique<Elastic>(1, Elastic::Params{2.0e5, 0.0, 1.0e5});
  }
  static constexpr bool kRateDependent = false;
};

struct ElasticPPCase {
  static std::unique_ptr<UniaxialMaterial> make() {
    return std::make_unique<ElasticPP>(2, ElasticPP::Params{2.0e5, 0.002, -0.001, 0.0005});
  }
  static double strainScale() { return 0.002; }
  static std::vector<double> path() { return cyclicPath(strainScale()); }
  static constexpr bool kRateDependent = false;
};

struct ElasticPPGapTensionCase {
  static std::unique_ptr<UniaxialMaterial> make() {
    return std::make_unique<ElasticPPGap>(3, ElasticPPGap::Params{1.0e5, 50.0, 0.001, 0.05, false});
  }
  static double strainScale() { return 0.001; }
  static std::vector<double> path() {
    return cyclicPath(strainScale(), {0.5, 1.3, 2.0, 1.2, 3.0, 1.6, 2.2, 4.0, -1.0, 0.0});
  }
  static constexpr bool kRateDependent = false;
};

struct ElasticPPGapCompressionDamageCase {
  static std::unique_ptr<UniaxialMaterial> make() {
    return std::make_unique<ElasticPPGap>(4, ElasticPPGap::Params{1.0e5, -50.0, -0.001, 0.0, true});
  }
  static double strainScale() { return 0.001; }
  static std::vector<double> path() {
    return cyclicPath(strainScale(), {-0.5, -1.3, -2.0, -1.2, -3.0, -1.6, -4.0, 1.0, 0.0});
  }
  static constexpr bool kRateDependent = false;
};

struct Steel01Case {
  static std::unique_ptr<UniaxialMaterial> make() {
    return std::make_unique<Steel01>(5, Steel01::Params{400.0, 2.0e5, 0.02, 0.1, 2.0, 0.1, 2.0});
  }
  static double strainScale() { return 0.002; }
  static std::vector<double> path() { return cyclicPath(strainScale()); }
  static constexpr bool kRateDependent = false;
};

struct Steel02Case {
  static std::unique_ptr<UniaxialMaterial> make() {
    Steel02::Params p{400.0, 2.0e5, 0.01};
    p.a1 = 0.02;
    p.a3 = 0.02;
    return std::make_unique<Steel02>(6, p);
  }
  static double strainScale() { return 0.002; }
  static std::vector<double> path() { return cyclicPath(strainScale()); }
  static constexpr bool kRateDependent = false;
};

struct Concrete01Case {
  static std::unique_ptr<UniaxialMaterial> make() {
    return std::make_unique<Concrete01>(7, Concrete01::Params{-30.0, -0.002, -6.0, -0.006});
  }
  static double strainScale() { return 0.002; }
  static std::vector<double> path() {
    return cyclicPath(strainScale(), {-0.5, -1.5, -0.5, 0.3, -2.5, -1.0, -4.0, 0.5, -1.0});
  }
  static constexpr bool kRateDependent = false;
};

struct Concrete02Case {
  static std::unique_ptr<UniaxialMaterial> make() {
    return std::make_unique<Concrete02>(
        8, Concrete02::Params{-30.0, -0.002, -6.0, -0.006, 0.1, 3.0, 1500.0});
  }
  static double strainScale() { return 0.002; }
  static std::vector<double> path() {
    return cyclicPath(strainScale(),
                      {0.03, 0.2, -0.5, -1.5, -0.5, 0.3, -2.5, -1.0, -4.0, 0.5, -1.0});
  }
  static constexpr bool kRateDependent = false;
};

struct ViscousCase {
  static std::unique_ptr<UniaxialMaterial> make() {
    return std::make_unique<Viscous>(9, Viscous::Params{100.0, 0.5, 1e-11});
  }
  static double strainScale() { return 0.002; }
  static std::vector<double> path() { return cyclicPath(strainScale()); }
  static constexpr bool kRateDependent = true;
};

struct ENTCase {
  static std::unique_ptr<UniaxialMaterial> make() {
    return std::make_unique<ENT>(10, ENT::Params{1000.0});
  }
  static double strainScale() { return 0.001; }
  static std::vector<double> path() { return cyclicPath(strainScale()); }
  static constexpr bool kRateDependent = false;
};

struct ParallelCase {
  static std::unique_ptr<UniaxialMaterial> make() {
    const Steel01 steel(1, Steel01::Params{400.0, 2.0e5, 0.02});
    const Elastic dashpot(2, Elastic::Params{1.0e4, 50.0, std::nullopt});
    return std::make_unique<Parallel>(11, Parallel::Params{{&steel, &dashpot}, {2.0, 0.5}});
  }
  static double strainScale() { return 0.002; }
  static std::vector<double> path() { return cyclicPath(strainScale()); }
  static constexpr bool kRateDependent = true;
};

struct SeriesCase {
  static std::unique_ptr<UniaxialMaterial> make() {
    const Steel01 steel(1, Steel01::Params{400.0, 2.0e5, 0.02});
    const Elastic spring(2, Elastic::Params{4.0e5, 0.0, std::nullopt});
    return std::make_unique<Series>(12, Series::Params{{&steel, &spring}});
  }
  static double strainScale() { return 0.003; }  // 400/2e5 + 400/4e5
  static std::vector<double> path() { return cyclicPath(strainScale()); }
  static constexpr bool kRateDependent = false;
};

using AllMaterials =
    ::testing::Types<ElasticCase, ElasticNoDampingCase, ElasticPPCase, ElasticPPGapTensionCase,
                     ElasticPPGapCompressionDamageCase, Steel01Case, Steel02Case, Concrete01Case,
                     Concrete02Case, ViscousCase, ENTCase, ParallelCase, SeriesCase>;
INSTANTIATE_TYPED_TEST_SUITE_P(Uniaxial, MaterialContract, AllMaterials);

}  // namespace
}  // namespace dabs::materials::testing
