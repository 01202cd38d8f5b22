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
    // Two passes: the material calls first, then the sums in a loop without calls, whose nine
    // accumulators stay in registers (a call would make the compiler save them every fiber).
    Status status = Status::Ok;
    const std::size_t n = mats_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Status s = mats_[i].setTrialStrain(e0 - y_[i] * kz + z_[i] * ky);
      if (!ok(s)) status = s;
    }
    addTo(sums, false);
    return status;
  }

  void addTo(FiberSums& sums, bool initial) const override {
    FiberSums local = sums;
    const std::size_t n = mats_.size();
    if (initial) {
      for (std::size_t i = 0; i < n; ++i) local.add(y_[i], z_[i], 0.0, mats_[i].getInitialTangent() * area_[i]);
    } else {
      for (std::size_t i = 0; i < n; ++i)
        local.add(y_[i], z_[i], mats_[i].getStress() * area_[i], mats_[i].getTangent() * area_[i]);
    }
    sums = local;
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
