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
  double stress(int i) const override { return object(i).getStress(); }
  double strain(int i) const override { return object(i).getStrain(); }
  int materialTag() const override { return mats_.empty() ? 0 : object(0).tag(); }

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
    else
      return typeid(material) == typeid(M);
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
  Status setTrialPlanar(double e0, double kz, FiberSums& sums) override {
    return setTrial(e0, kz, 0.0, sums);
  }

  void addTo(FiberSums& sums, bool initial) const override {
    FiberSums local = sums;
    const std::size_t n = mats_.size();
    if (initial) {
      for (std::size_t i = 0; i < n; ++i)
        local.add(y_[i], z_[i], 0.0, mats_[i].getInitialTangent() * area_[i]);
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
  const UniaxialMaterial& object(int i) const {
    if constexpr (std::is_same_v<M, BoxedMaterial>)
      return mats_[static_cast<std::size_t>(i)].material();
    else
      return mats_[static_cast<std::size_t>(i)];
  }
  std::vector<M> mats_;
  std::type_index type_ = std::type_index(typeid(void));
};

/// Fibers of one material (one parameter set, the prototype's) kept as arrays of committed and
/// trial states; the update is M::computeTrial. Fibers of another material of the same class
/// (other parameters) go to another group.
template <class M>
class StateFiberGroup final : public FiberGroup {
 public:
  using State = typename M::State;
  /// `prototype` is the material object whose fibers this group holds (identity decides
  /// membership) and whose parameters it uses.
  explicit StateFiberGroup(const M& prototype) : law_(prototype), source_(&prototype) {}

  double stress(int i) const override { return current()[static_cast<std::size_t>(i)].stress; }
  double strain(int i) const override { return current()[static_cast<std::size_t>(i)].strain; }
  int materialTag() const override { return law_.tag(); }

  void add(double y, double z, double area, const UniaxialMaterial& /*prototype*/) override {
    y_.push_back(y);
    z_.push_back(z);
    area_.push_back(area);
    committed_.push_back(law_.virginState());
    trial_.push_back(law_.virginState());
  }
  bool accepts(const UniaxialMaterial& material) const override { return &material == source_; }

  Status setTrial(double e0, double kz, double ky, FiberSums& sums) override {
    return sweep<false>(e0, kz, ky, sums);
  }
  Status setTrialPlanar(double e0, double kz, FiberSums& sums) override {
    return sweep<true>(e0, kz, 0.0, sums);
  }
  void addTo(FiberSums& sums, bool initial) const override {
    FiberSums local = sums;
    const std::size_t n = trial_.size();
    if (initial) {
      const double e0 = law_.getInitialTangent();
      for (std::size_t i = 0; i < n; ++i) local.add(y_[i], z_[i], 0.0, e0 * area_[i]);
    } else {
      const std::vector<State>& states = current();
      for (std::size_t i = 0; i < n; ++i)
        local.add(y_[i], z_[i], states[i].stress * area_[i], states[i].tangent * area_[i]);
    }
    sums = local;
  }
  // Every setTrial writes all trial states from the committed ones, so a commit can swap the two
  // arrays instead of copying (on large models the copy streamed the whole state array through
  // memory once more per step), and a revert only has to forget the trial.
  void commitState() override {
    if (trialIsNew_) std::swap(committed_, trial_);
    trialIsNew_ = false;
  }
  void revertToLastCommit() override { trialIsNew_ = false; }
  void revertToStart() override {
    std::fill(committed_.begin(), committed_.end(), law_.virginState());
    trialIsNew_ = false;
  }
  std::unique_ptr<FiberGroup> clone() const override {
    return std::make_unique<StateFiberGroup>(*this);
  }

 private:
  /// One pass: the update is inlined (no call to save the accumulators around), and each fiber's
  /// state is summed while it is in cache; on large models the state arrays do not fit in it. A
  /// plane section skips the z terms (a third of the sums).
  template <bool Planar>
  Status sweep(double e0, double kz, double ky, FiberSums& sums) {
    FiberSums local = sums;
    const std::size_t n = trial_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const double y = y_[i], a = area_[i];
      State& t = trial_[i];
      // The only failure of these laws is a non-finite stress or tangent, and it makes the
      // sums non-finite too: the caller checks those once instead of every fiber here.
      if constexpr (Planar) {
        static_cast<void>(law_.computeTrial(committed_[i], t, e0 - y * kz));
        local.addPlanar(y, t.stress * a, t.tangent * a);
      } else {
        const double z = z_[i];
        static_cast<void>(law_.computeTrial(committed_[i], t, e0 - y * kz + z * ky));
        local.add(y, z, t.stress * a, t.tangent * a);
      }
    }
    sums = local;
    trialIsNew_ = true;
    return Status::Ok;
  }

  /// The states the fibers are in: the trial ones after a setTrial, the committed ones after a
  /// commit or revert (then trial_ holds stale values, overwritten by the next setTrial).
  const std::vector<State>& current() const { return trialIsNew_ ? trial_ : committed_; }

  M law_;                           ///< parameters (its own state is not used)
  const UniaxialMaterial* source_;  ///< only compared with, while the section is built
  std::vector<State> committed_, trial_;
  bool trialIsNew_ = false;  ///< trial_ was computed after the last commit or revert
};

template <class M>
bool isA(const UniaxialMaterial& m) {
  return typeid(m) == typeid(M);
}

}  // namespace

template <class M>
std::unique_ptr<FiberGroup> stateGroup(const UniaxialMaterial& prototype) {
  return std::make_unique<StateFiberGroup<M>>(static_cast<const M&>(prototype));
}

std::unique_ptr<FiberGroup> FiberGroup::forMaterial(const UniaxialMaterial& prototype) {
  if (isA<Concrete02>(prototype)) return stateGroup<Concrete02>(prototype);
  if (isA<Steel02>(prototype)) return stateGroup<Steel02>(prototype);
  if (isA<Concrete01>(prototype)) return stateGroup<Concrete01>(prototype);
  if (isA<Steel01>(prototype)) return std::make_unique<TypedFiberGroup<Steel01>>();
  if (isA<Elastic>(prototype)) return std::make_unique<TypedFiberGroup<Elastic>>();
  if (isA<ElasticPP>(prototype)) return std::make_unique<TypedFiberGroup<ElasticPP>>();
  return std::make_unique<TypedFiberGroup<BoxedMaterial>>();
}

}  // namespace dabs::materials::section
