// SPDX-License-Identifier: MIT
#include "elements/link/YoshidaBearing3d.h"

#include <Eigen/Geometry>
#include <cassert>
#include <cmath>
#include <sstream>

#include "elements/Congruence.h"

namespace dabs::elements {

namespace {

constexpr double kCoincident = 1e-12;  // node distance (relative) below which nodes coincide
constexpr double kParallel = 1e-8;     // |a x b| / (|a||b|) below which vectors are parallel
constexpr double kLimitRounding =
    1e-12;  // a strain within this relative distance counts as at the limit

void requireFinite(double v, const char* field) {
  if (!std::isfinite(v)) throw InputError(field, "must be a finite number");
}

bool reached(double strain, double limit) { return strain >= limit * (1.0 - kLimitRounding); }

}  // namespace

void YoshidaBearing3d::Params::validate() const {
  if (vertical) {
    // Tr and Kv follow from the geometry (KumarVertical): the element replaces them.
    vertical->validate();
  } else {
    requireFinite(Tr, "Tr");
    requireFinite(Kv, "Kv");
    if (Tr <= 0.0) throw InputError("Tr", "must be positive");
    if (Kv <= 0.0) throw InputError("Kv", "must be positive");
  }
  requireFinite(Kt, "Kt");
  requireFinite(Kry, "Kr");
  requireFinite(Krz, "Kr");
  requireFinite(mass, "mass");
  requireFinite(designLimit, "design");
  requireFinite(failureLimit, "failure");
  if (Kt < 0.0) throw InputError("Kt", "must not be negative");
  if (Kry < 0.0 || Krz < 0.0) throw InputError("Kr", "must not be negative");
  if (mass < 0.0) throw InputError("mass", "must not be negative");
  if (designLimit <= 0.0) throw InputError("design", "must be positive");
  if (failureLimit < designLimit) throw InputError("failure", "must not be below the design limit");
  if (afterFailure == AfterFailure::Drop) {
    requireFinite(seat.h, "h");
    requireFinite(seat.Ks, "Ks");
    requireFinite(seat.muS, "mu_s");
    requireFinite(seat.muK, "mu_k");
    requireFinite(seat.Kst, "Kst");
    if (seat.h < 0.0) throw InputError("h", "(drop height) must not be negative");
    if (seat.Ks <= 0.0) throw InputError("Ks", "(seat stiffness) must be positive");
    if (seat.muS < 0.0) throw InputError("mu_s", "must not be negative");
    if (seat.muK < 0.0) throw InputError("mu_k", "must not be negative");
    if (seat.muK > seat.muS) throw InputError("mu_k", "must not exceed mu_s");
    if (seat.Kst <= 0.0) throw InputError("Kst", "(seat tangential stiffness) must be positive");
  }
  if (orientX.has_value() != orientY.has_value())
    throw InputError("orient", "needs both the x and the y vector");
  if (orientX) {
    if (!orientX->allFinite() || !orientY->allFinite())
      throw InputError("orient", "vectors must be finite");
    const double nx = orientX->norm(), ny = orientY->norm();
    if (nx == 0.0) throw InputError("orient", "x vector must not be zero");
    if (ny == 0.0) throw InputError("orient", "y vector must not be zero");
    if (orientX->cross(*orientY).norm() <= kParallel * nx * ny)
      throw InputError("orient", "y vector must not be parallel to the x vector");
  }
}

YoshidaBearing3d::YoshidaBearing3d(int tag, int iNode, int jNode,
                                   const materials::BiaxialMaterial& material, const Params& p)
    : FixedSizeElement(tag, {iNode, jNode}),
      material_(material.clone()),
      p_(p),
      seatCone_{p.seat.Kst, 0.0, p.seat.muS, p.seat.muK} {
  if (p.vertical) {
    vertical_.emplace(*p.vertical);
    p_.Tr = vertical_->Tr();
    p_.Kv = vertical_->Kv0();
  }
  assert(p_.Tr > 0.0 && p_.Kv > 0.0);
  for (int node = 0; node < 2; ++node)
    for (int d = 0; d < 3; ++d) m_(6 * node + d, 6 * node + d) = 0.5 * p.mass;
}

void YoshidaBearing3d::initialize(const NodalCoordinates& x) {
  if (x.size() != 2) throw InputError("nodes", "a yoshidaBearing needs 2 nodes");
  const Eigen::Vector3d axis = x[1] - x[0];
  const double scale = std::max({1.0, x[0].norm(), x[1].norm()});
  length_ = axis.norm();
  Eigen::Vector3d ex;
  if (length_ > kCoincident * scale) {
    ex = axis / length_;
    if (p_.orientX && ex.cross(*p_.orientX).norm() + std::max(0.0, -ex.dot(*p_.orientX)) >
                          kParallel * p_.orientX->norm())
      throw InputError("orient", "x vector must point from iNode to jNode for nodes apart");
  } else {
    length_ = 0.0;
    ex = p_.orientX ? Eigen::Vector3d(p_.orientX->normalized()) : Eigen::Vector3d::UnitZ();
  }
  Eigen::Vector3d y = p_.orientY ? *p_.orientY : Eigen::Vector3d::UnitX();
  if (!p_.orientY && ex.cross(y).norm() <= kParallel) y = Eigen::Vector3d::UnitY();
  y -= y.dot(ex) * ex;
  if (y.norm() <= kParallel * (p_.orientY ? p_.orientY->norm() : 1.0))
    throw InputError("orient", "y vector must not be parallel to the bearing axis");
  const Eigen::Vector3d ey = y.normalized();
  const Eigen::Vector3d ez = ex.cross(ey);
  axes_.row(0) = ex.transpose();
  axes_.row(1) = ey.transpose();
  axes_.row(2) = ez.transpose();

  // Local compatibility matrix (see the class comment), local dofs [u_i th_i u_j th_j].
  Eigen::Matrix<double, 6, kNumDof> bl = Eigen::Matrix<double, 6, kNumDof>::Zero();
  const double h = 0.5 * length_;
  bl(0, 0) = -1.0, bl(0, 6) = 1.0;
  bl(1, 1) = -1.0, bl(1, 7) = 1.0, bl(1, 5) = -h, bl(1, 11) = -h;
  bl(2, 2) = -1.0, bl(2, 8) = 1.0, bl(2, 4) = h, bl(2, 10) = h;
  bl(3, 3) = -1.0, bl(3, 9) = 1.0;
  bl(4, 4) = -1.0, bl(4, 10) = 1.0;
  bl(5, 5) = -1.0, bl(5, 11) = 1.0;
  for (int blk = 0; blk < 4; ++blk) b_.middleCols<3>(3 * blk) = bl.middleCols<3>(3 * blk) * axes_;
  for (int node = 0; node < 2; ++node) {
    mz_.segment<3>(6 * node + 3) = ez;
    my_.segment<3>(6 * node + 3) = ey;
  }

  revertToStart();
  k0_ = k_;
}

Status YoshidaBearing3d::update(const Kinematics& trial) {
  if (!trial.u.allFinite()) return Status::NonFinite;
  State& t = trial_;
  t = committed_;
  t.deformation.noalias() = b_ * trial.u;
  Eigen::Vector2d rate = Eigen::Vector2d::Zero();
  if (trial.v.size() == kNumDof) rate = (b_.middleRows<2>(1) * trial.v);
  const Eigen::Vector2d u = t.deformation.segment<2>(1);

  BasicMatrix kb = BasicMatrix::Zero();
  kb(0, 0) = p_.Kv;
  kb(3, 3) = p_.Kt;
  kb(4, 4) = p_.Kry;
  kb(5, 5) = p_.Krz;
  Basic q = kb * t.deformation;
  if (dropping()) {
    q.setZero();
    kb.setZero();
    seatContact(t, q, kb);
  } else if (!released()) {
    const Status s = material_->setTrialStrain(u, rate, trial.dt);
    if (!ok(s)) return s;
    q.segment<2>(1) = material_->getStress();
    kb.block<2, 2>(1, 1) = material_->getTangent();
  }
  if (vertical_ && !dropping()) {
    // Kumar et al. (2014): N(d0, |U|); dN/dU = dN/d|U| U/|U| (taken as zero at U = 0).
    const double uh = u.norm();
    const KumarVertical::Response r =
        vertical_->evaluate(t.deformation(0), uh, committed_.vertical);
    q(0) = r.N;
    kb(0, 0) = r.dNdu;
    if (uh > 0.0) kb.block<1, 2>(0, 1) = r.dNduh / uh * u.transpose();
    t.vertical = r.state;
  }
  t.basicForce = q;

  // Damage by shear strain in any direction of the shear plane.
  t.shearStrain = u.norm() / p_.Tr;
  t.maxShearStrain = std::max(committed_.maxShearStrain, t.shearStrain);
  if (!committed_.failed && reached(t.shearStrain, p_.failureLimit)) {
    t.failed = true;
    t.failureTime = trial.time;
  }
  assemble(q, kb);
  if (p_.pDelta && !t.dropped) addPDelta(t.deformation, q, kb);
  return Status::Ok;
}

void YoshidaBearing3d::seatContact(State& t, Basic& q, BasicMatrix& kb) const {
  t.dropped = true;
  t.seatGap = p_.seat.h + t.deformation(0);
  t.seatForce.setZero();
  t.sliding = false;
  const Eigen::Vector2d s = t.deformation.segment<2>(1);
  if (t.seatGap >= 0.0) {  // open: no force, the stick point follows node j
    t.stickPoint = s;
    return;
  }
  const double ks = p_.seat.Ks;
  const double normal = -ks * t.seatGap;
  q(0) = -normal;
  kb(0, 0) = ks;
  // In the first step after the rupture the stick point is where j stood when it was committed.
  const Eigen::Vector2d stick = committed_.dropped
                                    ? committed_.stickPoint
                                    : Eigen::Vector2d(committed_.deformation.segment<2>(1));
  const Eigen::Vector2d d = s - stick;
  const auto r = seatCone_.returnMap<double>({d(0), d(1)}, normal, {0.0, 0.0},
                                             committed_.dropped && committed_.sliding);
  // r.force is the seat's force on node j; the element's resisting force at j is its opposite.
  q(1) = -r.force[0];
  q(2) = -r.force[1];
  t.seatForce << normal, r.force[0], r.force[1];
  t.stickPoint = s - r.elasticAfter;
  t.sliding = r.sliding && seatCone_.active();
  t.seatDissipated = committed_.seatDissipated + r.plasticSlip * std::hypot(q(1), q(2));
  if (!seatCone_.active()) return;
  if (!r.sliding) {
    kb(1, 1) = kb(2, 2) = seatCone_.Kt;
    return;
  }
  // q_s = mu_k N n with n = d / |d| (no dashpot, so the trial force is -Kt d):
  // dq_s/ds = mu_k N (I - n n^T) / |d|, dq_s/dd0 = mu_k n dN/dd0 = -mu_k Ks n.
  const double dn = d.norm();
  const Eigen::Vector2d n = d / dn;
  kb.block<2, 2>(1, 1) =
      seatCone_.muK * normal / dn * (Eigen::Matrix2d::Identity() - n * n.transpose());
  kb.block<2, 1>(1, 0) = -seatCone_.muK * ks * n;
}

void YoshidaBearing3d::assemble(const Basic& q, const BasicMatrix& kb) {
  f_.noalias() = b_.transpose() * q;
  k_ = congruence(b_, kb);
}

void YoshidaBearing3d::addPDelta(const Basic& d, const Basic& q, const BasicMatrix& kb) {
  // The couple of N at j and -N at i, offset by (d1, d2), balanced half at each end
  // (ElastomericX's P-Delta moments): f += N/2 (d1 mz - d2 my). Its derivative holds dN/du
  // (the axial row of the basic tangent, with dN/dU for the Kumar law) and N dd/du.
  const double n = q(0);
  f_.noalias() += 0.5 * n * (d(1) * mz_ - d(2) * my_);
  const Eigen::Matrix<double, 1, kNumDof> dn = kb.row(0) * b_;
  k_.noalias() += 0.5 * mz_ * (d(1) * dn + n * b_.row(1));
  k_.noalias() -= 0.5 * my_ * (d(2) * dn + n * b_.row(2));
}

void YoshidaBearing3d::commitState() {
  material_->commitState();
  committed_ = trial_;
  kc_ = k_;
}

void YoshidaBearing3d::revertToLastCommit() {
  material_->revertToLastCommit();
  trial_ = committed_;
}

void YoshidaBearing3d::revertToStart() {
  material_->revertToStart();
  trial_ = committed_ = State{};
  BasicMatrix kb = BasicMatrix::Zero();
  kb(0, 0) = p_.Kv;
  kb(3, 3) = p_.Kt;
  kb(4, 4) = p_.Kry;
  kb(5, 5) = p_.Krz;
  kb.block<2, 2>(1, 1) = material_->getInitialTangent();
  assemble(Basic::Zero(), kb);
  kc_ = k_;
}

int YoshidaBearing3d::damage() const noexcept {
  if (trial_.failed) return 2;
  return reached(trial_.maxShearStrain, p_.designLimit) ? 1 : 0;
}

std::optional<Eigen::VectorXd> YoshidaBearing3d::response(std::span<const std::string> args) const {
  if (args.size() != 1) return std::nullopt;
  const std::string& name = args[0];
  auto scalar = [](double v) { return Eigen::VectorXd::Constant(1, v); };
  if (name == "force" || name == "forces" || name == "globalForce" || name == "globalForces")
    return Eigen::VectorXd(f_);
  if (name == "localForce" || name == "localForces") {
    Eigen::VectorXd fl(kNumDof);
    for (int blk = 0; blk < 4; ++blk) fl.segment<3>(3 * blk) = axes_ * f_.segment<3>(3 * blk);
    return fl;
  }
  if (name == "basicForce" || name == "basicForces") return Eigen::VectorXd(trial_.basicForce);
  if (name == "deformation" || name == "deformations" || name == "basicDeformation")
    return Eigen::VectorXd(trial_.deformation);
  if (name == "shearStrain") return scalar(trial_.shearStrain);
  if (name == "maxShearStrain") return scalar(trial_.maxShearStrain);
  if (name == "damage") return scalar(damage());
  if (name == "failureTime") return scalar(trial_.failureTime);
  if (name == "dropped") return scalar(trial_.dropped ? 1.0 : 0.0);
  if (name == "seatGap") return scalar(trial_.seatGap);
  if (name == "seatForce") return Eigen::VectorXd(trial_.seatForce);
  if (name == "seatStatus")
    return scalar(trial_.dropped && trial_.seatGap < 0.0 ? (trial_.sliding ? 2.0 : 1.0) : 0.0);
  if (name == "seatDissipatedEnergy") return scalar(trial_.seatDissipated);
  if (vertical_) {
    const double uh = trial_.deformation.segment<2>(1).norm();
    if (name == "verticalStiffness") return scalar(vertical_->stiffness(uh));
    if (name == "criticalLoad") return scalar(vertical_->criticalLoad(uh));
    if (name == "cavitationForce") return scalar(trial_.vertical.cavitationRatio * vertical_->Fc());
    if (name == "maxTension") return scalar(trial_.vertical.umax);
    if (name == "verticalBranch") return scalar(trial_.vertical.branch);
  }
  if (name == "hystereticForce" || name == "viscousForce" || name == "backForce" ||
      name == "dissipatedEnergy")
    return material_->response(name);
  return std::nullopt;
}

std::string YoshidaBearing3d::describe() const {
  std::ostringstream out;
  out << Element::describe() << " material " << material_->tag() << " Tr " << p_.Tr << " Kv "
      << p_.Kv << " Kt " << p_.Kt << " Kr " << p_.Kry << " " << p_.Krz << " mass " << p_.mass
      << " limits " << p_.designLimit << " " << p_.failureLimit << " afterFailure "
      << afterFailureName(p_.afterFailure);
  if (p_.afterFailure == AfterFailure::Drop)
    out << " " << p_.seat.h << " seat " << p_.seat.Ks << " " << p_.seat.muS << " " << p_.seat.muK
        << " " << p_.seat.Kst;
  if (vertical_) {
    const auto& v = vertical_->params();
    out << " vertical kumar " << v.G << " " << v.Kbulk << " " << v.Di << " " << v.Do << " " << v.ts
        << " " << v.tr << " " << v.n << " tc " << v.tc << " kc " << v.kc << " phi " << v.phi
        << " ac " << v.ac << " cavitation " << v.cavitation << " buckling " << v.buckling
        << " kvShear " << v.kvShear;
  }
  if (p_.pDelta) out << " pDelta";
  out << " damage " << damage();
  return out.str();
}

const char* YoshidaBearing3d::afterFailureName(AfterFailure mode) noexcept {
  switch (mode) {
    case AfterFailure::Keep: return "keep";
    case AfterFailure::Release: return "release";
    case AfterFailure::Stop: return "stop";
    case AfterFailure::Drop: return "drop";
  }
  return "keep";
}

}  // namespace dabs::elements
