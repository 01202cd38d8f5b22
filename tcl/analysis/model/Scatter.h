// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "elements/Element.h"
#include "elements/FarPair.h"
#include "materials/Status.h"
#include "tcl/domain/Domain.h"

namespace dabs::analysis {

/// One entry of a vector scatter: local dof `local` adds coef times its value to equation `eq`.
struct VecEntry {
  int local;
  int eq;
  double coef;
};

/// One entry of a matrix scatter: offset j*n+i of (row i, column j) in the column-major local
/// matrix adds coef times its value to the sparse matrix's value `value` (an index into
/// valuePtr()).
struct MatEntry {
  int local;
  int value;
  double coef;
};

/// How one element meets the equations, built once per matrix pattern by AnalysisModel: where its
/// force and matrices go (indexed adds, style.md section 10), the buffers its updates gather into
/// and what the assembly needs to know of it. Written to by the model's build alone, but for the
/// work buffers and the flags the tangent and residual keep.
struct ElementScatter {
  elements::Element* element = nullptr;
  std::vector<domain::Node*> nodes;
  std::vector<VecEntry> vec;
  /// The element's matrix entries (those of Element::matrixSupport when it names them), sorted
  /// by value; empty when matSlots scatters.
  std::vector<MatEntry> mat;
  /// With `direct` (every dof one equation or none, coefficient 1): `mat` without its
  /// coefficients, half the bytes that the assembly of every iteration reads for every
  /// nonlinear element. Pairs (local, value).
  std::vector<std::pair<int, int>> matSlots;
  std::vector<std::pair<int, int>> rowCol;  ///< (row, column) of each mat entry while building
  domain::RayleighFactors rayleigh;
  bool rayleighOn = false;
  Eigen::VectorXd u, v, a;  ///< gather buffers
  /// Per local dof its equation (coefficient 1) or -1 when prescribed; empty when some dof is a
  /// combination (constraints), and then `vec` scatters.
  std::vector<int> direct;
  /// Whether updates gather velocities and accelerations: a linear element without a damping
  /// tangent has a force that depends on its displacements alone, and the residual needs its
  /// rates only when the elements form their own inertia and damping forces.
  bool rates = true;
  /// Element::isLinear, read once at the build: the tangent's assembly passes over the linear
  /// elements (most of a long viaduct's) without touching their objects, which a pass over the
  /// fiber states has evicted from the cache.
  bool linear = false;
  /// The force is the element's initial stiffness times its displacements, with no support
  /// value driven by a pattern among them (Element::forceIsInitialStiffnessTimesDisplacements):
  /// the residual forms it with every such element's as one product with their assembled
  /// stiffness, the element is not updated, and the domain forms its state when it is read
  /// (Domain::setStateDeferred). On the benchmark's linear frame the updates and force scatters
  /// of its 1,330 beams were a third of the run.
  bool deferred = false;
  mutable Eigen::VectorXd force;  ///< residual work buffer
  Eigen::MatrixXd work;           ///< tangent work buffer
  /// A nonlinear element's constant matrix terms (mass, initial-stiffness Rayleigh damping) are
  /// in the tangent's constant part: was it active when that part was formed?
  bool constantActive = false;
  /// An element that may turn inactive (Element::mayTurnInactive) with mass or Rayleigh damping:
  /// left out of the residual's constant matrices; the residual adds its inertia and damping
  /// forces itself while it is active.
  bool ownDynamics = false;
  elements::FarPair* far = nullptr;  ///< a contact pair that may sleep (Element::farPair)
  bool sleeping = false;             ///< left out of the pattern and the iterations
  bool switching = false;    ///< the element's force switches between laws (Element::HeldStatus)
  bool scalesSteps = false;  ///< the element may ask Newton for a longer step (newtonStepScale)

  /// Gather and work buffers for n dofs (once).
  void allocateBuffers(int n) {
    if (u.size() == n) return;
    u = v = a = force = Eigen::VectorXd::Zero(n);
    work = Eigen::MatrixXd::Zero(n, n);
  }

  /// Gathers the nodes' trial velocities and accelerations (alone: for an element whose update
  /// is skipped while the residual still reads its rates); NonFinite when one is not finite.
  [[nodiscard]] Status gatherRates() {
    double* pv = v.data();
    double* pa = a.data();
    // x * 0 is 0 for a finite x and NaN for an infinite or NaN one, so `check` is 0 exactly when
    // every value is finite (one pass, no branch per value).
    double check = 0.0;
    for (const domain::Node* n : nodes) {
      const int ndf = n->ndf();
      const double* nv = n->vel.data();
      const double* na = n->accel.data();
      for (int d = 0; d < ndf; ++d) {
        pv[d] = nv[d];
        pa[d] = na[d];
        check += nv[d] * 0.0;
      }
      pv += ndf;
      pa += ndf;
    }
    return check == 0.0 ? Status::Ok : Status::NonFinite;
  }

  /// Gathers the nodes' trial response (the rates only when `rates`) and updates the element at
  /// time t (step dt).
  [[nodiscard]] Status update(double t, double dt) {
    double* pu = u.data();
    double check = 0.0;  // as in gatherRates
    for (const domain::Node* n : nodes) {
      const int ndf = n->ndf();
      const double* nu = n->disp.data();
      for (int d = 0; d < ndf; ++d) {
        pu[d] = nu[d];
        check += nu[d] * 0.0;
      }
      pu += ndf;
    }
    if (rates && !ok(gatherRates())) return Status::NonFinite;
    if (check != 0.0) return Status::NonFinite;
    return element->update(elements::Kinematics{u, v, a, t, dt});
  }

  /// Adds a local matrix (numDof x numDof) to the matrix values through the scatter indices.
  void addMatrix(double* values, const Eigen::MatrixXd& m) const {
    const double* local = m.data();
    if (matSlots.empty()) {
      addEntries(values, [local](int i) { return local[i]; });
      return;
    }
    for (const auto& [offset, value] : matSlots) values[value] += local[offset];
  }

  /// values[e.value] += e.coef * entry(e.local) over `mat`, one value's run of entries (`mat` is
  /// sorted by value) summed in a register in their order: the same sums as one by one in
  /// memory, without a store and reload between two terms of one value.
  template <class Entry>
  void addEntries(double* values, Entry entry) const {
    const MatEntry* e = mat.data();
    const MatEntry* const end = e + mat.size();
    while (e != end) {
      const int value = e->value;
      double sum = values[value];
      do {
        sum += e->coef * entry(e->local);
        ++e;
      } while (e != end && e->value == value);
      values[value] = sum;
    }
  }

  /// B -= the local force f through the element's equations.
  void subtractForce(const Eigen::Ref<const Eigen::VectorXd>& f, Eigen::VectorXd& B) const {
    if (direct.empty()) {
      for (const VecEntry& e : vec) B(e.eq) -= e.coef * f(e.local);
      return;
    }
    const auto n = static_cast<Eigen::Index>(direct.size());
    for (Eigen::Index i = 0; i < n; ++i)
      if (const int eq = direct[static_cast<std::size_t>(i)]; eq >= 0) B(eq) -= f(i);
  }
};

/// How one node meets the equations: its dofs' equations and its mass matrix's places.
struct NodeScatter {
  domain::Node* node = nullptr;
  int firstDof = 0;                         ///< index of the node's dof 0 among all node dofs
  std::vector<MatEntry> mass;               ///< nodal mass scatter (local = j*ndf+i)
  std::vector<std::pair<int, int>> rowCol;  ///< (row, column) of each mass entry while building
  std::vector<VecEntry> vec;
  double alphaM = 0.0;  ///< Rayleigh mass factor
};

}  // namespace dabs::analysis
