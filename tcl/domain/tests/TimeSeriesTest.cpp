// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "materials/InputError.h"
#include "tcl/domain/LoadPattern.h"
#include "tcl/domain/NearFaultPulseSeries.h"
#include "tcl/domain/PathSeries.h"
#include "tcl/domain/TrigSeries.h"

namespace dabs::domain {
namespace {

constexpr double kExact = 1e-12;

TEST(PathSeriesTest, InterpolatesLinearlyAndFollowsOpenSeesAtTheEnd) {
  PathSeries s(1, 0.5, {0.0, 2.0, 4.0, 3.0}, 10.0, 0.0, false);
  EXPECT_NEAR(s.factor(0.25), 10.0, kExact);
  EXPECT_NEAR(s.factor(1.25), 35.0, kExact);
  EXPECT_EQ(s.factor(1.5), 0.0);  // OpenSees PathSeries: zero from the last sample on
  PathSeries last(2, 0.5, {0.0, 2.0, 4.0, 3.0}, 10.0, 0.0, true);
  EXPECT_NEAR(last.factor(7.0), 30.0, kExact);
  EXPECT_EQ(s.factor(-0.1), 0.0);
}

TEST(PathSeriesTest, ReadsPeerNgaRecordHeader) {
  // Kobe Takatori EW: NPTS = 4096, DT = 0.01 s, PGA 0.671 g at 2.82 s
  // (verification/data/README.md).
  const RecordFile r = readRecordFile(std::string(DABS_DATA_DIR) + "/RSN1120_KOBE_TAK090.AT2");
  EXPECT_EQ(r.values.size(), 4096u);
  EXPECT_NEAR(r.dt, 0.01, kExact);
  std::size_t peak = 0;
  for (std::size_t i = 0; i < r.values.size(); ++i)
    if (std::abs(r.values[i]) > std::abs(r.values[peak])) peak = i;
  EXPECT_NEAR(std::abs(r.values[peak]), 0.671, 0.0005);
  EXPECT_NEAR(static_cast<double>(peak) * r.dt, 2.82, 0.015);
}

TEST(PathSeriesTest, ReadsElCentroWithTrailerAndRejectsBadFiles) {
  const RecordFile r = readRecordFile(std::string(DABS_DATA_DIR) + "/elCentro.at2");
  EXPECT_EQ(r.values.size(), 1559u);
  EXPECT_NEAR(r.dt, 0.02, kExact);
  EXPECT_THROW(readRecordFile("/nonexistent/record.at2"), InputError);
}

TEST(TrigSeriesTest, SineInsideItsWindowOnly) {
  TrigSeries s(1, 1.0, 3.0, 2.0, 5.0, 0.0, 0.0);
  EXPECT_NEAR(s.factor(1.5), 5.0, kExact);  // quarter period after tStart
  EXPECT_EQ(s.factor(0.5), 0.0);
  EXPECT_EQ(s.factor(3.5), 0.0);
}

TEST(GroundMotionTest, IntegratesConstantAccelerationExactly) {
  // a = 2 from t = 0: v = 2t, d = t^2 (trapezoid rule is exact for linear v, and second order for
  // d).
  auto accel =
      std::make_shared<PathSeries>(1, 0.01, std::vector<double>(1001, 2.0), 1.0, 0.0, true);
  GroundMotion gm(accel, nullptr, nullptr, 1.0);
  EXPECT_NEAR(gm.vel(3.0), 6.0, 1e-9);
  EXPECT_NEAR(gm.disp(3.0), 9.0, 1e-9);
  EXPECT_NEAR(gm.accel(3.0), 2.0, kExact);
}

TEST(LoadPatternTest, LoadConstFreezesTheFactor) {
  auto series = std::make_shared<PathSeries>(1, 1.0, std::vector<double>{0.0, 1.0, 2.0, 3.0}, 1.0,
                                             0.0, false);
  PlainPattern p(1, series, 2.0);
  EXPECT_NEAR(p.factor(1.5), 3.0, kExact);
  p.setConstant(1.5);
  EXPECT_NEAR(p.factor(0.0), 3.0, kExact);
}

TEST(NearFaultPulseTest, AccelerationIsTheDerivativeOfVelocity) {
  NearFaultPulseSeries::Params p;
  p.Tp = 1.2;
  p.Vp = 1.5;
  p.gamma = 2.2;
  p.nu = 0.7;
  p.t0 = 2.0;
  p.validate();
  NearFaultPulseSeries s(1, p);
  const double h = 1e-6;
  for (double t = 0.8; t < 3.2; t += 0.137) {
    const double fd = (s.velocity(t + h) - s.velocity(t - h)) / (2 * h);
    EXPECT_NEAR(s.factor(t), fd, 1e-6 * std::max(1.0, std::abs(fd)));
  }
  // Envelope peak: at t0 the velocity is Vp cos(nu) (eq. 1).
  EXPECT_NEAR(s.velocity(2.0), 1.5 * std::cos(0.7), kExact);
  EXPECT_EQ(s.factor(0.0), 0.0);
  EXPECT_EQ(s.velocity(2.0 + 0.5 * 2.2 * 1.2 + 1e-9), 0.0);
}

TEST(NearFaultPulseTest, RejectsBadParameters) {
  NearFaultPulseSeries::Params p;
  p.gamma = 1.0;
  EXPECT_THROW(p.validate(), InputError);
  p.gamma = 2.0;
  p.Tp = 1.0;
  p.t0 = 0.5;  // the pulse would start before t = 0
  EXPECT_THROW(p.validate(), InputError);
}

}  // namespace
}  // namespace dabs::domain
