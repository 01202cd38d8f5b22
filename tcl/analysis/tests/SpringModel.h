// SPDX-License-Identifier: MIT
#pragma once

#include <memory>

#include "elements/link/ZeroLength.h"
#include "tcl/domain/Domain.h"
#include "tcl/domain/LinearSeries.h"
#include "tcl/domain/LoadPattern.h"

namespace dabs::analysis::testing {

/// A one-dof model for integrator tests: node 1 fixed, node 2 (mass m) joined to it by a
/// zeroLength spring of the given material, and a reference load P0 on node 2 scaled by a linear
/// series (load factor = time).
inline void buildSpring(domain::Domain& domain,
                        std::unique_ptr<materials::UniaxialMaterial> material, double mass,
                        double P0) {
  domain.addNode(1, 1, 1, Eigen::Vector3d::Zero());
  domain::Node& n2 = domain.addNode(2, 1, 1, Eigen::Vector3d::Zero());
  if (mass > 0.0) n2.setMass(Eigen::MatrixXd::Constant(1, 1, mass));
  domain.addFix(1, 0);
  elements::ZeroLength::Params p;
  p.nodes = {1, 2};
  p.ndm = 1;
  p.ndf = 1;
  p.dirs = {1};
  std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats;
  mats.push_back(std::move(material));
  p.validate(mats.size());
  domain.addElement(std::make_unique<elements::ZeroLength>(1, p, std::move(mats)));
  auto pattern = std::make_unique<domain::PlainPattern>(
      1, std::make_shared<domain::LinearSeries>(1, 1.0), 1.0);
  pattern->loads.push_back({2, Eigen::VectorXd::Constant(1, P0)});
  domain.addPattern(std::move(pattern));
}

}  // namespace dabs::analysis::testing
