// SPDX-License-Identifier: MIT
#include "materials/section/FiberGroup.h"

#include <cstddef>
#include <type_traits>
#include <typeindex>
#include <typeinfo>

#include "materials/Concrete01.h"
#include "materials/Concrete02.h"
#include "materials/Elastic.h"
#include "materials/ElasticPP.h"
#include "materials/FourLanes.h"
#include "materials/Steel01.h"
#include "materials/Steel02.h"

namespace dabs::materials::section {

namespace {

/// Groups of fewer fibers sum in fiber order: their chains are short, and forming and adding
/// four partials would cost more (a plane section's bars at two heights are two fibers).
constexpr std::size_t kPartialSumsFrom = 8;

/// A group of fiber states (of kPartialSumsFrom fibers or more) sums its fibers into four partial
/// sums, fiber i into partial i % 4, pads the last four with fibers of no area, and adds the
/// partials as (0 + 1) + (2 + 3): four fibers at a time in AVX registers where the processor has
/// AVX, one at a time in the same order elsewhere, so the same bits on every machine. (Summed in
/// fiber order, as OpenSees sums, each of the nine sums is one chain of dependent additions, a
/// fiber's waiting for the last one's.)
template <bool Planar>
struct PartialSums {
  FiberSums part[4];

  void add(std::size_t i, double y, double z, double force, double stiffness) {
    if constexpr (Planar)
      part[i & 3].addPlanar(y, force, stiffness);
    else
      part[i & 3].add(y, z, force, stiffness);
  }
  /// Fibers n to the next multiple of four: no area, so no force and no stiffness.
  void pad(std::size_t n) {
    for (std::size_t i = n; i % 4 != 0; ++i) add(i, 0.0, 0.0, 0.0, 0.0);
  }
  void addTo(FiberSums& sums) const {
    const auto total = [this](double FiberSums::*x) {
      return (part[0].*x + part[1].*x) + (part[2].*x + part[3].*x);
    };
    sums.p += total(&FiberSums::p);
    sums.mz += total(&FiberSums::mz);
    sums.kPP += total(&FiberSums::kPP);
    sums.kPz += total(&FiberSums::kPz);
    sums.kzz += total(&FiberSums::kzz);
    if constexpr (!Planar) {
      sums.my += total(&FiberSums::my);
      sums.kPy += total(&FiberSums::kPy);
      sums.kzy += total(&FiberSums::kzy);
      sums.kyy += total(&FiberSums::kyy);
    }
  }
};

/// Adds n fibers to `sums` one at a time, in the order PartialSums describes (fiber order below
/// kPartialSumsFrom fibers); `response(i)` is fiber i's stress and tangent.
template <bool Planar, class Response>
void addOneByOne(const double* ys, const double* zs, const double* as, Response response,
                 std::size_t n, FiberSums& sums) {
  if (n < kPartialSumsFrom) {
    FiberSums local = sums;
    for (std::size_t i = 0; i < n; ++i) {
      const StressTangent r = response(i);
      const double a = as[i];
      if constexpr (Planar)
        local.addPlanar(ys[i], r.stress * a, r.tangent * a);
      else
        local.add(ys[i], zs[i], r.stress * a, r.tangent * a);
    }
    sums = local;
    return;
  }
  PartialSums<Planar> partial;
  for (std::size_t i = 0; i < n; ++i) {
    const StressTangent r = response(i);
    const double a = as[i];
    partial.add(i, ys[i], Planar ? 0.0 : zs[i], r.stress * a, r.tangent * a);
  }
  partial.pad(n);
  partial.addTo(sums);
}

#ifdef DABS_FOUR_LANES
/// The nine sums of four partials, lane k partial k; each lane does FiberSums::add's operations
/// in its order.
template <bool Planar>
struct SumLanes {
  __m256d p, mz, my, kPP, kPz, kPy, kzz, kzy, kyy;

  __attribute__((target("avx"))) void clear() {
    p = mz = my = kPP = kPz = kPy = kzz = kzy = kyy = _mm256_setzero_pd();
  }
  /// Four fibers: stresses, tangents, areas, y and z.
  __attribute__((target("avx"))) void add(__m256d stress, __m256d tangent, __m256d a, __m256d y,
                                          __m256d z) {
    const __m256d force = _mm256_mul_pd(stress, a);
    const __m256d stiffness = _mm256_mul_pd(tangent, a);
    const __m256d sy = _mm256_mul_pd(stiffness, y);
    p = _mm256_add_pd(p, force);
    mz = _mm256_sub_pd(mz, _mm256_mul_pd(force, y));
    kPP = _mm256_add_pd(kPP, stiffness);
    kPz = _mm256_sub_pd(kPz, sy);
    kzz = _mm256_add_pd(kzz, _mm256_mul_pd(sy, y));
    if constexpr (!Planar) {
      const __m256d sz = _mm256_mul_pd(stiffness, z);
      my = _mm256_add_pd(my, _mm256_mul_pd(force, z));
      kPy = _mm256_add_pd(kPy, sz);
      kzy = _mm256_sub_pd(kzy, _mm256_mul_pd(sy, z));
      kyy = _mm256_add_pd(kyy, _mm256_mul_pd(sz, z));
    }
  }
  /// (lane 0 + lane 1) + (lane 2 + lane 3).
  __attribute__((target("avx"))) static double total(__m256d v) {
    const __m256d pairs = _mm256_hadd_pd(v, v);
    return _mm_cvtsd_f64(
        _mm_add_sd(_mm256_castpd256_pd128(pairs), _mm256_extractf128_pd(pairs, 1)));
  }
  __attribute__((target("avx"))) void addTo(FiberSums& sums) const {
    sums.p += total(p);
    sums.mz += total(mz);
    sums.kPP += total(kPP);
    sums.kPz += total(kPz);
    sums.kzz += total(kzz);
    if constexpr (!Planar) {
      sums.my += total(my);
      sums.kPy += total(kPy);
      sums.kzy += total(kzy);
      sums.kyy += total(kyy);
    }
  }
};

/// addOneByOne's partial sums, four fibers at a time (AVX); the missing fibers of the last four
/// are loaded as zeros, the padding PartialSums adds.
template <bool Planar>
__attribute__((target("avx"))) void addFourAtOnce(const double* ys, const double* zs,
                                                  const double* as, const double* stresses,
                                                  const double* tangents, std::size_t n,
                                                  FiberSums& sums) {
  SumLanes<Planar> lanes;
  lanes.clear();
  const __m256d noZ = _mm256_setzero_pd();
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4)
    lanes.add(_mm256_loadu_pd(stresses + i), _mm256_loadu_pd(tangents + i), _mm256_loadu_pd(as + i),
              _mm256_loadu_pd(ys + i), Planar ? noZ : _mm256_loadu_pd(zs + i));
  if (i < n) {
    // The last one to three fibers by masked loads (no copies: a copy's stores would stall the
    // vector loads that read them).
    const long long left = static_cast<long long>(n - i);
    const auto lane = [left](long long k) { return k < left ? -1LL : 0LL; };
    const __m256i fibers = _mm256_set_epi64x(lane(3), lane(2), lane(1), lane(0));
    lanes.add(_mm256_maskload_pd(stresses + i, fibers), _mm256_maskload_pd(tangents + i, fibers),
              _mm256_maskload_pd(as + i, fibers), _mm256_maskload_pd(ys + i, fibers),
              Planar ? noZ : _mm256_maskload_pd(zs + i, fibers));
  }
  lanes.addTo(sums);
}
#endif

/// Adds the fibers' forces and tangents (fiber i's stress and tangent in stresses[i] and
/// tangents[i]) to `sums`, in the order PartialSums describes.
template <bool Planar>
void addResponses(const double* ys, const double* zs, const double* as, const double* stresses,
                  const double* tangents, std::size_t n, FiberSums& sums) {
#ifdef DABS_FOUR_LANES
  if (n >= kPartialSumsFrom && lanes::available()) {
    addFourAtOnce<Planar>(ys, zs, as, stresses, tangents, n, sums);
    return;
  }
#endif
  addOneByOne<Planar>(
      ys, zs, as,
      [stresses, tangents](std::size_t i) {
        return StressTangent{stresses[i], tangents[i]};
      },
      n, sums);
}

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
    addGeometry(y, z, area);
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
    const Geometry& g = geometry();
    const std::size_t n = mats_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Status s = mats_[i].setTrialStrain(e0 - g.y[i] * kz + g.z[i] * ky);
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
    const Geometry& g = geometry();
    const std::size_t n = mats_.size();
    if (initial) {
      for (std::size_t i = 0; i < n; ++i)
        local.add(g.y[i], g.z[i], 0.0, mats_[i].getInitialTangent() * g.area[i]);
    } else {
      for (std::size_t i = 0; i < n; ++i)
        local.add(g.y[i], g.z[i], mats_[i].getStress() * g.area[i],
                  mats_[i].getTangent() * g.area[i]);
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
  bool keepsStateAtSameStrains() const override {
    for (std::size_t i = 0; i < mats_.size(); ++i)
      if (!object(static_cast<int>(i)).keepsStateAtSameStrain()) return false;
    return true;
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

/// Fibers of one material (one parameter set, the prototype's) kept as an array of states,
/// four fibers' fields side by side (StateFours); the update is the law's computeTrials, four
/// fibers at a time.
///
/// The law's `commitTrial` forms the state its computeTrial leaves from the trial stress and
/// tangent (only the history updates), so the group keeps, besides its committed states, just the
/// trial stress and tangent of each fiber: a pass writes 16 bytes a fiber instead of a whole
/// state. A commit is then only noted; the next pass folds it in (commitTrials at the strains of
/// the committed pass) as it reads each state anyway. On a model whose fiber states do not fit in
/// the cache the passes are bound by memory traffic, and this saves the state writes of every
/// pass and a whole commit pass a step.
template <class M>
class StateFiberGroup final : public FiberGroup {
 public:
  using State = typename M::State;
  using Fours = StateFours<State>;
  static_assert(
      requires(const M& m, State& s, const Fours* c, Fours* f, const FiberStrains& e,
               const Responses& r) {
        m.commitTrial(s, 0.0, 0.0, 0.0);
        m.computeTrials(c, e, r, std::size_t{0});
        m.commitTrials(f, e, r, std::size_t{0});
      },
      "a law of this group updates and commits arrays of fours");
  /// `prototype` is the material object whose fibers this group holds (identity decides
  /// membership) and whose parameters it uses.
  explicit StateFiberGroup(const M& prototype) : law_(prototype), source_(&prototype) {}

  /// The stress the section's sums took (a fiber of a four may have it by other powers than its
  /// update one at a time: Steel02::computeTrials).
  double stress(int i) const override { return response(static_cast<std::size_t>(i)).stress; }
  double strain(int i) const override { return currentState(static_cast<std::size_t>(i)).strain; }
  int materialTag() const override { return law_.tag(); }

  void add(double y, double z, double area, const UniaxialMaterial& /*prototype*/) override {
    addGeometry(y, z, area);
    // A new four with every lane virgin (the lanes past the last fiber stay so).
    if (count_ % 4 == 0) committed_.push_back(Fours::filledWith(law_.virginState()));
    ++count_;
    trialStress_.push_back(0.0);
    trialTangent_.push_back(0.0);
  }
  bool accepts(const UniaxialMaterial& material) const override { return &material == source_; }

  Status setTrial(double e0, double kz, double ky, FiberSums& sums) override {
    return sweep<false>(e0, kz, ky, sums);
  }
  Status setTrialPlanar(double e0, double kz, FiberSums& sums) override {
    return sweep<true>(e0, kz, 0.0, sums);
  }
  void addTo(FiberSums& sums, bool initial) const override {
    // In the order of a pass's sums (the 3D sums; a plane section reads only the plane ones,
    // which are the same numbers).
    const Geometry& g = geometry();
    if (initial) {
      const double e0 = law_.getInitialTangent();
      addOneByOne<false>(
          g.y.data(), g.z.data(), g.area.data(),
          [e0](std::size_t) {
            return StressTangent{0.0, e0};
          },
          count_, sums);
    } else {
      addOneByOne<false>(
          g.y.data(), g.z.data(), g.area.data(), [this](std::size_t i) { return response(i); },
          count_, sums);
    }
  }
  // Every setTrial writes the trial of all fibers from the committed states, so a revert only
  // has to forget the trial.
  void commitState() override {
    if (phase_ == Phase::Trial) phase_ = Phase::CommitPending;
  }
  void revertToLastCommit() override {
    if (phase_ == Phase::Trial) phase_ = Phase::Committed;
  }
  void revertToStart() override {
    std::fill(committed_.begin(), committed_.end(), Fours::filledWith(law_.virginState()));
    phase_ = Phase::Committed;
  }
  std::unique_ptr<FiberGroup> clone() const override {
    return std::make_unique<StateFiberGroup>(*this);
  }
  bool keepsStateAtSameStrains() const override { return law_.keepsStateAtSameStrain(); }

 private:
  using Response = StressTangent;
  enum class Phase {
    Committed,      ///< committed_ is the current state; the trial arrays are stale
    Trial,          ///< the trial arrays hold the trial at the strains of the last setTrial
    CommitPending,  ///< that trial was committed; committed_ does not have it yet
  };

  template <bool Planar>
  Status sweep(double e0, double kz, double ky, FiberSums& sums) {
    if (phase_ == Phase::CommitPending)
      sweepFolding<Planar, true>(e0, kz, ky, sums);
    else
      sweepFolding<Planar, false>(e0, kz, ky, sums);
    return Status::Ok;
  }

  /// One pass: the updates, then the sums of the responses they just wrote (in L1: a group is one
  /// material of one section). Apart, the update loop has the registers to itself and the sums
  /// run over two small arrays: 7 % less time on the fiber bridges than one loop that did both
  /// (on the RC frame, whose groups are small, within 1 %); the sums in the order PartialSums
  /// describes. A plane section skips the z terms (a third of the sums). `Fold`: first commit
  /// each fiber's pending trial into its state.
  template <bool Planar, bool Fold>
  void sweepFolding(double e0, double kz, double ky, FiberSums& sums) {
    const Geometry& g = geometry();
    const double* ys = g.y.data();
    const double* zs = g.z.data();
    const double* as = g.area.data();
    const std::size_t n = count_;
    // The only failure of these laws is a non-finite stress or tangent, and it makes the sums
    // non-finite too: the caller checks those once instead of every fiber here.
    //
    // The laws form the fibers' strains from the section's as they read them (FiberStrains): no
    // array of strains a section long that each pass would write and the next fold read back (on
    // a model whose states do not fit in the cache, 16 of the about 130 bytes a pass moved a
    // fiber). The pending commits are at the strains of the committed pass, formed again.
    const Responses trial{trialStress_.data(), trialTangent_.data()};
    if constexpr (Fold)
      law_.commitTrials(committed_.data(), FiberStrains::ofSection(e0_, kz_, ky_, planar_, ys, zs),
                        trial, n);
    law_.computeTrials(committed_.data(), FiberStrains::ofSection(e0, kz, ky, Planar, ys, zs),
                       trial, n);
    addResponses<Planar>(ys, zs, as, trial.stress, trial.tangent, n, sums);
    e0_ = e0;
    kz_ = kz;
    ky_ = ky;
    planar_ = Planar;
    phase_ = Phase::Trial;
  }

  /// Fiber i's strain in the last setTrial.
  double trialStrain(std::size_t i) const {
    const Geometry& g = geometry();
    return FiberStrains::ofSection(e0_, kz_, ky_, planar_, g.y.data(), g.z.data())[i];
  }
  /// Fiber i's committed state as it is stored (without a pending commit).
  State stored(std::size_t i) const { return stateOf(committed_.data(), i); }
  /// The stress and tangent the fibers are at: the trial ones after a setTrial (also once
  /// committed), the committed states' after a revert.
  Response response(std::size_t i) const {
    if (phase_ == Phase::Committed) {
      const State c = stored(i);
      return {c.stress, c.tangent};
    }
    return {trialStress_[i], trialTangent_[i]};
  }
  /// Fiber i's whole current state (for responses; formed again from the committed one).
  State currentState(std::size_t i) const {
    State t = stored(i);
    if (phase_ == Phase::Committed) return t;
    if (phase_ == Phase::CommitPending) {
      law_.commitTrial(t, trialStrain(i), trialStress_[i], trialTangent_[i]);
      return t;
    }
    const State committed = t;
    static_cast<void>(law_.computeTrial(committed, t, trialStrain(i)));
    return t;
  }

  M law_;                           ///< parameters (its own state is not used)
  const UniaxialMaterial* source_;  ///< only compared with, while the section is built
  std::vector<Fours> committed_;    ///< the fibers' committed states, four to an element
  std::size_t count_ = 0;           ///< fibers
  /// The fibers' trial stresses and tangents (lanes::store writes four of each as one vector)
  std::vector<double> trialStress_, trialTangent_;
  double e0_ = 0.0, kz_ = 0.0, ky_ = 0.0;  ///< section strains of the last setTrial
  bool planar_ = false;                    ///< the last setTrial was a plane one
  Phase phase_ = Phase::Committed;
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
