// SPDX-License-Identifier: MIT
#include "elements/Element.h"

#include <sstream>

namespace dabs::elements {

namespace {
// Zero matrices shared by elements without damping or mass. They are never written, so sharing
// them is safe (unlike the mutable static scratch matrices style.md section 3 forbids).
const Eigen::MatrixXd& zeroMatrix(int n) {
  static const Eigen::MatrixXd kZero = Eigen::MatrixXd::Zero(24, 24);
  if (n <= 24) return kZero;
  static const Eigen::MatrixXd kBigZero = Eigen::MatrixXd::Zero(96, 96);
  return kBigZero;
}
}  // namespace

Eigen::Ref<const Eigen::MatrixXd> Element::dampingTangent() const {
  const int n = numDof();
  return zeroMatrix(n).topLeftCorner(n, n);
}

Eigen::Ref<const Eigen::MatrixXd> Element::mass() const {
  const int n = numDof();
  return zeroMatrix(n).topLeftCorner(n, n);
}

void Element::addLoad(const BeamLoad& /*load*/, double /*factor*/) {
  throw InputError(
      "", std::string(typeName()) + " element " + std::to_string(tag()) + " takes no member loads");
}

std::optional<Eigen::VectorXd> Element::response(std::span<const std::string> args) const {
  if (args.size() == 1 && (args[0] == "force" || args[0] == "forces" || args[0] == "globalForce" ||
                           args[0] == "globalForces")) {
    return Eigen::VectorXd(resistingForce());
  }
  return std::nullopt;
}

std::string Element::describe() const {
  std::ostringstream out;
  out << "Element " << tag() << " " << typeName() << " nodes:";
  for (int n : nodeTags()) out << " " << n;
  return out.str();
}

}  // namespace dabs::elements
