// SPDX-License-Identifier: MIT
#include "materials/section/FiberSection.h"

#include <array>
#include <cstdlib>
#include <limits>
#include <string>

#include "materials/InputError.h"
#include "materials/ResponseArgs.h"

namespace dabs::materials::section {

namespace {
constexpr std::array kCodes2d{SectionCode::P, SectionCode::Mz};
constexpr std::array kCodes3d{SectionCode::P, SectionCode::Mz, SectionCode::My, SectionCode::T};
}  // namespace

template <int Ndm>
FiberSection<Ndm>::FiberSection(int tag, const std::vector<Fiber>& fibers, double torsionStiffness)
    : SectionForceDeformation(tag), gj_(torsionStiffness) {
  if (fibers.empty()) throw InputError("section Fiber " + std::to_string(tag), "has no fibers");
  if (Ndm == 3 && !(torsionStiffness >= 0.0)) throw InputError("-GJ", "must be zero or positive");
  for (const Fiber& f : fibers) {
    if (!(f.area > 0.0)) throw InputError("fiber area", "must be positive");
    if (f.material == nullptr) throw InputError("fiber material", "is missing");
    y_.push_back(f.y);
    z_.push_back(f.z);
    area_.push_back(f.area);
    mats_.push_back(f.material->clone());
  }
  for (auto& m : mats_) m->revertToStart();
  e_ = eCommitted_ = Eigen::VectorXd::Zero(kOrder);
  s_ = Eigen::VectorXd::Zero(kOrder);
  k_ = k0_ = Eigen::MatrixXd::Zero(kOrder, kOrder);
  sumFibers(true);
  sumFibers(false);
}

template <int Ndm>
FiberSection<Ndm>::FiberSection(const FiberSection& o)
    : SectionForceDeformation(o), y_(o.y_), z_(o.z_), area_(o.area_), gj_(o.gj_), e_(o.e_), eCommitted_(o.eCommitted_),
      s_(o.s_), k_(o.k_), k0_(o.k0_) {
  for (const auto& m : o.mats_) mats_.push_back(m->clone());
}

template <int Ndm>
std::span<const SectionCode> FiberSection<Ndm>::type() const {
  if constexpr (Ndm == 2) return kCodes2d;
  else return kCodes3d;
}

// Resultants and tangent by midpoint quadrature over the fibers: with the strain-displacement row
// a = [1, -y] (2D) or [1, -y, z] (3D), s = sum(sigma A a), k = sum(Et A a a^T).
template <int Ndm>
void FiberSection<Ndm>::sumFibers(bool initial) {
  Eigen::MatrixXd& k = initial ? k0_ : k_;
  k.setZero();
  if (!initial) s_.setZero();
  const int n = numFibers();
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d a(1.0, -y_[i], z_[i]);
    const double et =
        (initial ? mats_[i]->getInitialTangent() : mats_[i]->getTangent()) * area_[i];
    constexpr int m = Ndm == 2 ? 2 : 3;
    k.topLeftCorner(m, m) += et * a.head<m>() * a.head<m>().transpose();
    if (!initial) s_.head(m) += mats_[i]->getStress() * area_[i] * a.head<m>();
  }
  if constexpr (Ndm == 3) {
    k(3, 3) = gj_;
    if (!initial) s_(3) = gj_ * e_(3);
  }
}

template <int Ndm>
Status FiberSection<Ndm>::setTrialDeformation(const Eigen::Ref<const Eigen::VectorXd>& e) {
  e_ = e;
  const double kz = e(1), ky = Ndm == 3 ? e(2) : 0.0;
  Status status = Status::Ok;
  const int n = numFibers();
  for (int i = 0; i < n; ++i) {
    const Status s = mats_[i]->setTrialStrain(e(0) - y_[i] * kz + z_[i] * ky);
    if (!ok(s)) status = s;
  }
  sumFibers(false);
  if (ok(status) && !s_.allFinite()) status = Status::NonFinite;
  return status;
}

template <int Ndm>
void FiberSection<Ndm>::commitState() {
  for (auto& m : mats_) m->commitState();
  eCommitted_ = e_;
}

template <int Ndm>
void FiberSection<Ndm>::revertToLastCommit() {
  for (auto& m : mats_) m->revertToLastCommit();
  e_ = eCommitted_;
  sumFibers(false);
}

template <int Ndm>
void FiberSection<Ndm>::revertToStart() {
  for (auto& m : mats_) m->revertToStart();
  e_.setZero();
  eCommitted_.setZero();
  sumFibers(false);
}

template <int Ndm>
std::optional<Eigen::VectorXd> FiberSection<Ndm>::response(
    std::span<const std::string> args) const {
  if (args.empty()) return std::nullopt;
  if (args.size() == 1 && (args[0] == "force" || args[0] == "forces")) return s_;
  if (args.size() == 1 && (args[0] == "deformation" || args[0] == "deformations")) return e_;
  // fiber y z ?matTag? response: the words must be whole numbers ("abc" or NaN name no fiber).
  if (args[0] == "fiber" && (args.size() == 4 || args.size() == 5)) {
    const std::optional<double> yWord = responseReal(args[1]);
    const std::optional<double> zWord = responseReal(args[2]);
    const std::optional<int> matWord = args.size() == 5 ? responseInteger(args[3]) : std::optional<int>(0);
    if (!yWord || !zWord || !matWord) return std::nullopt;
    const double y = *yWord;
    const double z = *zWord;
    const int matTag = *matWord;
    const bool byMaterial = args.size() == 5;
    int best = -1;
    double bestD = std::numeric_limits<double>::infinity();
    for (int i = 0; i < numFibers(); ++i) {
      if (byMaterial && mats_[i]->tag() != matTag) continue;
      const double d = (y_[i] - y) * (y_[i] - y) + (Ndm == 3 ? (z_[i] - z) * (z_[i] - z) : 0.0);
      if (d < bestD) {
        bestD = d;
        best = i;
      }
    }
    if (best < 0 || args.back() != "stressStrain") return std::nullopt;
    Eigen::VectorXd out(2);
    out << mats_[best]->getStress(), mats_[best]->getStrain();
    return out;
  }
  return std::nullopt;
}

template class FiberSection<2>;
template class FiberSection<3>;

}  // namespace dabs::materials::section
