// SPDX-License-Identifier: MIT
#pragma once

#include <stdexcept>
#include <string>

namespace dabs {

/// A parameter that cannot make a valid model. Thrown by `Params::validate()` and by builders;
/// caught only in tcl/commands, which turns it into a Tcl error naming the command and argument.
class InputError : public std::runtime_error {
 public:
  /// `field` names the offending parameter as the user wrote it (e.g. "Fy"); `reason` says what
  /// was expected (e.g. "must be positive").
  InputError(std::string field, std::string reason)
      : std::runtime_error(field.empty() ? reason : field + " " + reason),
        field_(std::move(field)),
        reason_(std::move(reason)) {}

  /// Name of the offending parameter (may be empty when the error concerns the whole input).
  const std::string& field() const noexcept { return field_; }
  /// What was expected.
  const std::string& reason() const noexcept { return reason_; }

 private:
  std::string field_;
  std::string reason_;
};

}  // namespace dabs
