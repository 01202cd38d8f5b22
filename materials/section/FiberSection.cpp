// SPDX-License-Identifier: MIT
#include "materials/section/FiberSection.h"

#include <algorithm>
#include <cmath>

#include <array>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <tuple>

#include "materials/InputError.h"
#include "materials/ResponseArgs.h"

namespace dabs::materials::section {

namespace {
constexpr std::array kCodes2d{SectionCode::P, SectionCode::Mz};
constexpr std::array kCodes3d{SectionCode::P, SectionCode::Mz, SectionCode::My, SectionCode::T};
}  // namespace

template <int Ndm>
FiberSection<Ndm>::FiberSection(int tag, const std::vector<Fiber>& fibers, double torsionStiffness,
                                bool aboutCentroid)
    : SectionForceDeformation(tag), gj_(torsionStiffness) {
  if (fibers.empty()) throw InputError("section Fiber " + std::to_string(tag), "has no fibers");
  if (Ndm == 3 && !(torsionStiffness >= 0.0)) throw InputError("-GJ", "must be zero or positive");
  if (aboutCentroid) {
    double area = 0.0, qz = 0.0, qy = 0.0, extent = 0.0;
    for (const Fiber& f : fibers) {
      area += f.area;
      qz += f.y * f.area;
      qy += f.z * f.area;
      extent = std::max({extent, std::abs(f.y), std::abs(f.z)});
    }
    // A symmetric section's sums leave a centroid of round-off size (1e-17 m for a circular
    // pier): that is the axis itself, so it stays exactly there and such a section gives the
    // same numbers with and without -noCentroid.
    const double roundOff = 1e-12 * extent;
    if (area > 0.0) {
      yBar_ = qz / area;
      if (Ndm == 3) zBar_ = qy / area;
      if (std::abs(yBar_) <= roundOff) yBar_ = 0.0;
      if (std::abs(zBar_) <= roundOff) zBar_ = 0.0;
    }
  }
  auto places = std::make_shared<std::vector<Place>>();
  // Fibers of one material at one strain point ((y, z); y alone in a plane section, whose
  // strain is eps - y kz) have the same strain history and so the same states: they are
  // evaluated once, with their areas summed. Plane sections given with several fibers across
  // the width (patches divided in z, bars in a layer at one depth) have many such.
  std::map<std::tuple<const UniaxialMaterial*, double, double>, std::pair<std::size_t, int>>
      evaluated;
  for (const Fiber& f : fibers) {
    if (!(f.area > 0.0)) throw InputError("fiber area", "must be positive");
    if (f.material == nullptr) throw InputError("fiber material", "is missing");
    const auto key = std::make_tuple(f.material, f.y, Ndm == 3 ? f.z : 0.0);
    if (const auto found = evaluated.find(key); found != evaluated.end()) {
      const auto [g, index] = found->second;
      groups_[g]->addArea(index, f.area);
      places->push_back({f.y, f.z, f.area, g, index});
      continue;
    }
    std::size_t g = 0;
    while (g < groups_.size() && !groups_[g]->accepts(*f.material)) ++g;
    if (g == groups_.size()) groups_.push_back(FiberGroup::forMaterial(*f.material));
    // 2D sections ignore z (the strain is eps - y kz); keep it for responses only.
    groups_[g]->add(f.y - yBar_, f.z - zBar_, f.area, *f.material);
    const int index = groups_[g]->size() - 1;
    evaluated.emplace(key, std::make_pair(g, index));
    places->push_back({f.y, f.z, f.area, g, index});
  }
  places_ = std::move(places);
  for (const auto& g : groups_) evaluatedFibers_ += g->size();
  FiberSums initial;
  for (const auto& g : groups_) g->addTo(initial, true);
  store(initial, true);
  sumCurrent();
}

template <int Ndm>
FiberSection<Ndm>::FiberSection(const FiberSection& o)
    : SectionForceDeformation(o),
      places_(o.places_),
      gj_(o.gj_),
      e_(o.e_),
      eCommitted_(o.eCommitted_),
      s_(o.s_),
      k_(o.k_),
      k0_(o.k0_),
      materialUpdates_(o.materialUpdates_),
      evaluatedFibers_(o.evaluatedFibers_),
      yBar_(o.yBar_),
      zBar_(o.zBar_) {
  for (const auto& g : o.groups_) groups_.push_back(g->clone());
}

template <int Ndm>
std::span<const SectionCode> FiberSection<Ndm>::type() const {
  if constexpr (Ndm == 2)
    return kCodes2d;
  else
    return kCodes3d;
}

// Resultants and tangent by midpoint quadrature over the fibers: with the strain-displacement row
// a = [1, -y] (2D) or [1, -y, z] (3D), s = sum(sigma A a), k = sum(Et A a a^T).
template <int Ndm>
void FiberSection<Ndm>::store(const FiberSums& f, bool initial) {
  Matrix& k = initial ? k0_ : k_;
  k(0, 0) = f.kPP;
  k(0, 1) = k(1, 0) = f.kPz;
  k(1, 1) = f.kzz;
  if (!initial) {
    s_(0) = f.p;
    s_(1) = f.mz;
  }
  if constexpr (Ndm == 3) {
    k(0, 2) = k(2, 0) = f.kPy;
    k(1, 2) = k(2, 1) = f.kzy;
    k(2, 2) = f.kyy;
    k(3, 3) = gj_;
    if (!initial) {
      s_(2) = f.my;
      s_(3) = gj_ * e_(3);
    }
  }
}

template <int Ndm>
void FiberSection<Ndm>::sumCurrent() {
  FiberSums sums;
  for (const auto& g : groups_) g->addTo(sums, false);
  store(sums, false);
}

template <int Ndm>
Status FiberSection<Ndm>::setTrialDeformation(const Eigen::Ref<const Eigen::VectorXd>& e) {
  e_ = e;
  const double kz = e_(1), ky = Ndm == 3 ? e_(2) : 0.0;
  Status status = Status::Ok;
  FiberSums sums;
  for (const auto& g : groups_) {
    const Status s =
        Ndm == 2 ? g->setTrialPlanar(e_(0), kz, sums) : g->setTrial(e_(0), kz, ky, sums);
    if (!ok(s)) status = s;
  }
  materialUpdates_ += evaluatedFibers_;
  store(sums, false);
  if (ok(status) && !(s_.allFinite() && k_.allFinite())) status = Status::NonFinite;
  return status;
}

template <int Ndm>
void FiberSection<Ndm>::commitState() {
  for (auto& g : groups_) g->commitState();
  eCommitted_ = e_;
}

template <int Ndm>
void FiberSection<Ndm>::revertToLastCommit() {
  for (auto& g : groups_) g->revertToLastCommit();
  e_ = eCommitted_;
  sumCurrent();
}

template <int Ndm>
void FiberSection<Ndm>::revertToStart() {
  for (auto& g : groups_) g->revertToStart();
  e_.setZero();
  eCommitted_.setZero();
  sumCurrent();
}

template <int Ndm>
std::optional<Eigen::VectorXd> FiberSection<Ndm>::response(
    std::span<const std::string> args) const {
  if (args.empty()) return std::nullopt;
  if (args.size() == 1 && (args[0] == "force" || args[0] == "forces")) return Eigen::VectorXd(s_);
  if (args.size() == 1 && (args[0] == "deformation" || args[0] == "deformations"))
    return Eigen::VectorXd(e_);
  // fiber y z ?matTag? response: the words must be whole numbers ("abc" or NaN name no fiber).
  if (args[0] == "fiber" && (args.size() == 4 || args.size() == 5)) {
    const std::optional<double> yWord = responseReal(args[1]);
    const std::optional<double> zWord = responseReal(args[2]);
    const std::optional<int> matWord =
        args.size() == 5 ? responseInteger(args[3]) : std::optional<int>(0);
    if (!yWord || !zWord || !matWord) return std::nullopt;
    const double y = *yWord;
    const double z = *zWord;
    const int matTag = *matWord;
    const bool byMaterial = args.size() == 5;
    int best = -1;
    double bestD = std::numeric_limits<double>::infinity();
    for (int i = 0; i < numFibers(); ++i) {
      if (byMaterial && fiberMaterialTag(i) != matTag) continue;
      const double dy = fiberY(i) - y, dz = fiberZ(i) - z;
      const double d = dy * dy + (Ndm == 3 ? dz * dz : 0.0);
      if (d < bestD) {
        bestD = d;
        best = i;
      }
    }
    if (best < 0 || args.back() != "stressStrain") return std::nullopt;
    Eigen::VectorXd out(2);
    out << fiberStress(best), fiberStrain(best);
    return out;
  }
  return std::nullopt;
}

template class FiberSection<2>;
template class FiberSection<3>;

}  // namespace dabs::materials::section
