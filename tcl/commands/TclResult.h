// SPDX-License-Identifier: MIT
#pragma once

#include <tcl.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "tcl/commands/Runtime.h"

namespace dabs::tcl {

/// Sets the interpreter result to a number, a list of numbers or a string.
void setResult(Runtime& rt, int value);
void setResult(Runtime& rt, double value);
void setResult(Runtime& rt, const std::string& value);
void setResult(Runtime& rt, const std::vector<double>& values);
void setResult(Runtime& rt, const std::vector<int>& values);
void setResult(Runtime& rt, const Eigen::Ref<const Eigen::VectorXd>& values);

}  // namespace dabs::tcl
