// SPDX-License-Identifier: MIT
#include "materials/section/FiberGroup.h"

#include <type_traits>
#include <typeindex>
#include <typeinfo>

#include "materials/Concrete01.h"
#include "materials/Concrete02.h"
#include "materials/Elastic.h"
#include "materials/ElasticPP.h"
#include "materials/Steel01.h"
#include "materials/Steel02.h"

namespace dabs::materials::section {

namespace {

/// Any uniaxial material held by pointer, with the calls a fiber loop makes (virtual ones).
class BoxedMaterial {
 public:
  explicit BoxedMaterial(const UniaxialMaterial& m) : m_(m.clone()) { m_->revertToStart(); }
  BoxedMaterial(const BoxedMaterial& o) : m_(o.m_->clone()) {}
  BoxedMaterial(BoxedMaterial&&) noexcept = default;
  BoxedMaterial& operator=(const BoxedMaterial&) = delete;

  Status setTrialStrain(double strain) { return m_->setTrialStrain(strain); }
  double getStress() const { return m_->getStress(); }
  double getTangent() const { return m_->getTangent(); }
  double getInitialTangent() const { return m_->getInitialTangent(); }
  void commitState() { m_->commitState(); }
  void revertToLastCommit() { m_->revertToLastCommit(); }
  void revertToStart() { m_->revertToStart(); }
  const UniaxialMaterial& material() const { return *m_; }

 private:
  std::unique_ptr<UniaxialMaterial> m_;
};

/// Fibers of one material class M held by value. M is a final class (direct calls) or
/// BoxedMaterial (any class, virtual calls).
template <class M>
class TypedFiberGroup final : public FiberGroup {
 public:
  const UniaxialMaterial& material(int i) const override {
    if constexpr (std::is_same_v<M, BoxedMaterial>) return mats_[static_cast<std::size_t>(i)].material();
    else return mats_[static_cast<std::size_t>(i)];
  }

  void add(double y, double z, double area, const UniaxialMaterial& prototype) override {
    if (mats_.empty()) type_ = std::type_index(typeid(prototype));
    y_.push_back(y);
    z_.push_back(z);
    area_.push_back(area);
    if constexpr (std::is_same_v<M, BoxedMaterial>) {
      mats_.emplace_back(prototype);
    } else {
      mats_.push_back(static_cast<const M&>(prototype));
      mats_.back().revertToStart();
    }
  }

  bool accepts(const UniaxialMaterial& material) const override {
    if constexpr (std::is_same_v<M, BoxedMaterial>)
      return mats_.empty() || std::type_index(typeid(material)) == type_;
    else return typeid(material) == typeid(M);
  }

  Status setTrial(double e0, double kz, double ky, FiberSums& sums) override {
    FiberSums local = sums;  // a local copy stays in registers across the material calls
    Status status = Status::Ok;
    const std::size_t n = mats_.size();
    for (std::size_t i = 0; i < n; ++i) {
      M& m = mats_[i];
      const double y = y_[i], z = z_[i], a = area_[i];
      const Status s = m.setTrialStrain(e0 - y * kz + z * ky);
      if (!ok(s)) status = s;
      local.add(y, z, m.getStress() * a, m.getTangent() * a);
    }
    sums = local;
    return status;
  }

  void addTo(FiberSums& sums, bool initial) const override {
    const std::size_t n = mats_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const M& m = mats_[i];
      const double a = area_[i];
      if (initial) sums.add(y_[i], z_[i], 0.0, m.getInitialTangent() * a);
      else sums.add(y_[i], z_[i], m.getStress() * a, m.getTangent() * a);
    }
  }

  void commitState() override {
    for (M& m : mats_) m.commitState();
  }
  void revertToLastCommit() override {
    for (M& m : mats_) m.revertToLastCommit();
  }
  void revertToStart() override {
    for (M& m : mats_) m.revertToStart();
  }
  std::unique_ptr<FiberGroup> clone() const override {
    return std::make_unique<TypedFiberGroup>(*this);
  }

 private:
  std::vector<M> mats_;
  std::type_index type_ = std::type_index(typeid(void));
};

template <class M>
bool isA(const UniaxialMaterial& m) {
  return typeid(m) == typeid(M);
}

}  // namespace

std::unique_ptr<FiberGroup> FiberGroup::forMaterial(const UniaxialMaterial& prototype) {
  if (isA<Concrete02>(prototype)) return std::make_unique<TypedFiberGroup<Concrete02>>();
  if (isA<Steel02>(prototype)) return std::make_unique<TypedFiberGroup<Steel02>>();
  if (isA<Concrete01>(prototype)) return std::make_unique<TypedFiberGroup<Concrete01>>();
  if (isA<Steel01>(prototype)) return std::make_unique<TypedFiberGroup<Steel01>>();
  if (isA<Elastic>(prototype)) return std::make_unique<TypedFiberGroup<Elastic>>();
  if (isA<ElasticPP>(prototype)) return std::make_unique<TypedFiberGroup<ElasticPP>>();
  return std::make_unique<TypedFiberGroup<BoxedMaterial>>();
}

}  // namespace dabs::materials::section
