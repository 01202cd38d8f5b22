// SPDX-License-Identifier: MIT
#include "tcl/commands/ArgReader.h"

#include "materials/InputError.h"

#include <algorithm>
#include <cassert>
#include <cctype>
#include <cmath>
#include <limits>

namespace dabs::tcl {

namespace {
constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

bool parseReal(Tcl_Obj* obj, double& value) {
  return Tcl_GetDoubleFromObj(nullptr, obj, &value) == TCL_OK && std::isfinite(value);
}
// Tcl_GetIntFromObj accepts any value that fits in 32 bits unsigned and wraps it (4294967295
// becomes -1), so a tag that does not fit would name another object; read 64 bits and check.
bool parseInteger(Tcl_Obj* obj, int& value) {
  Tcl_WideInt wide = 0;
  if (Tcl_GetWideIntFromObj(nullptr, obj, &wide) != TCL_OK) return false;
  if (wide < std::numeric_limits<int>::min() || wide > std::numeric_limits<int>::max())
    return false;
  value = static_cast<int>(wide);
  return true;
}

}  // namespace

bool isIntegerWord(std::string_view t) noexcept {
  if (!t.empty() && (t[0] == '-' || t[0] == '+')) t.remove_prefix(1);
  return !t.empty() && std::all_of(t.begin(), t.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  });
}

std::string integerExpectation(Tcl_Obj* obj) {
  if (obj != nullptr && isIntegerWord(Tcl_GetString(obj)))
    return "expected an integer from " + std::to_string(std::numeric_limits<int>::min()) + " to " +
           std::to_string(std::numeric_limits<int>::max());
  return "expected an integer";
}

std::optional<int> integerValue(Tcl_Obj* obj) {
  int value = 0;
  if (obj == nullptr || !parseInteger(obj, value)) return std::nullopt;
  return value;
}

std::optional<double> realValue(Tcl_Obj* obj) {
  double value = 0.0;
  if (obj == nullptr || !parseReal(obj, value)) return std::nullopt;
  return value;
}

bool isOptionWord(std::string_view token) noexcept {
  return token.size() >= 2 && token[0] == '-' &&
         std::isalpha(static_cast<unsigned char>(token[1])) != 0;
}

ArgReader::ArgReader(int objc, Tcl_Obj* const objv[], std::string usage, int first)
    : tokens_(objv, objv + objc),
      used_(static_cast<std::size_t>(objc), false),
      usage_(std::move(usage)) {
  for (int i = 0; i < first && i < objc; ++i) used_[static_cast<std::size_t>(i)] = true;
  std::string ctx;
  for (int i = 0; i < first && i < objc; ++i) {
    if (i > 0) ctx += ' ';
    ctx += Tcl_GetString(objv[i]);
  }
  context_ = ctx;
}

std::string_view ArgReader::text(std::size_t i) const { return Tcl_GetString(tokens_[i]); }

std::size_t ArgReader::nextUnread() const {
  while (firstUnread_ < tokens_.size() && used_[firstUnread_]) ++firstUnread_;
  return firstUnread_;
}

bool ArgReader::hasMore() const { return nextUnread() < tokens_.size(); }

bool ArgReader::hasPositional() const {
  const std::size_t i = nextUnread();
  return i < tokens_.size() && !isOptionWord(text(i));
}

std::string_view ArgReader::peek() const {
  const std::size_t i = nextUnread();
  return i < tokens_.size() ? text(i) : std::string_view{};
}

void ArgReader::fail(std::size_t pos, std::string_view name, std::string_view what) const {
  std::string msg = context_ + ": argument " + std::to_string(pos) + " (" + std::string(name) +
                    ") " + std::string(what);
  if (!usage_.empty()) msg += "; usage: " + usage_;
  throw ArgError(msg);
}

void ArgReader::fail(std::string_view what) const {
  std::string msg = context_ + ": " + std::string(what);
  if (!usage_.empty()) msg += "; usage: " + usage_;
  throw ArgError(msg);
}

void ArgReader::record(std::string_view name, std::size_t i) { named_.emplace_back(name, i); }

const std::pair<std::string, std::size_t>* ArgReader::readUnder(std::string_view name) const {
  for (auto it = named_.rbegin(); it != named_.rend(); ++it) {
    std::string_view recorded = it->first;
    if (recorded == name || (isOptionWord(recorded) && recorded.substr(1) == name)) return &*it;
  }
  return nullptr;
}

std::size_t ArgReader::positionOf(std::string_view name) const noexcept {
  const auto* read = readUnder(name);
  return read != nullptr ? read->second : 0;
}

void ArgReader::failArgument(std::string_view name, std::string_view what) const {
  const auto* read = readUnder(name);
  if (read == nullptr || read->second >= tokens_.size())
    fail(std::string(name) + " " + std::string(what));
  // Named as the user wrote it (an option with its '-').
  fail(read->second, read->first,
       std::string(what) + ", got \"" + std::string(text(read->second)) + "\"");
}

void ArgReader::failArgument(std::string_view name, std::size_t index,
                             std::string_view what) const {
  const auto* read = readUnder(name);
  if (read == nullptr || read->second + index >= tokens_.size())
    fail(std::string(name) + " " + std::string(what));
  const std::size_t pos = read->second + index;
  fail(pos, read->first, std::string(what) + ", got \"" + std::string(text(pos)) + "\"");
}

void ArgReader::failInput(const InputError& error) const {
  // The field is often the subject of the reason ("node" + "7 does not exist"), so the message
  // keeps the error's own sentence and adds the token only when the sentence lacks it.
  const std::size_t pos = error.field().empty() ? 0 : positionOf(error.field());
  if (pos == 0 || pos >= tokens_.size()) fail(error.what());
  std::string msg = context_ + ": argument " + std::to_string(pos) + ": " + error.what();
  const std::string_view token = text(pos);
  if (std::string_view(error.what()).find(token) == std::string_view::npos)
    msg += ", got \"" + std::string(token) + "\"";
  if (!usage_.empty()) msg += "; usage: " + usage_;
  throw ArgError(msg);
}

void ArgReader::expected(std::size_t i, std::string_view name, std::string_view what) const {
  if (i >= tokens_.size()) fail(i, name, std::string(what) + ", got nothing (too few arguments)");
  fail(i, name, std::string(what) + ", got \"" + std::string(text(i)) + "\"");
}

int ArgReader::integer(std::string_view name) {
  const std::size_t i = nextUnread();
  int value = 0;
  if (i >= tokens_.size() || !parseInteger(tokens_[i], value))
    expected(i, name, integerExpectation(i < tokens_.size() ? tokens_[i] : nullptr));
  used_[i] = true;
  last_ = i;
  record(name, i);
  return value;
}

double ArgReader::real(std::string_view name) {
  const std::size_t i = nextUnread();
  double value = 0.0;
  if (i >= tokens_.size() || !parseReal(tokens_[i], value)) expected(i, name, "expected a number");
  used_[i] = true;
  last_ = i;
  record(name, i);
  return value;
}

std::string ArgReader::word(std::string_view name) {
  const std::size_t i = nextUnread();
  if (i >= tokens_.size()) expected(i, name, "expected a word");
  used_[i] = true;
  last_ = i;
  record(name, i);
  return std::string(text(i));
}

Tcl_Obj* ArgReader::object(std::string_view name) {
  const std::size_t i = nextUnread();
  if (i >= tokens_.size()) expected(i, name, "expected a value");
  used_[i] = true;
  last_ = i;
  record(name, i);
  return tokens_[i];
}

std::optional<double> ArgReader::optionalReal(std::string_view name) {
  if (!hasPositional()) return std::nullopt;
  return real(name);
}

std::optional<int> ArgReader::optionalInteger(std::string_view name) {
  if (!hasPositional()) return std::nullopt;
  return integer(name);
}

std::vector<int> ArgReader::integers(std::string_view name, std::size_t atLeast) {
  std::vector<int> out;
  while (hasPositional()) {
    int value = 0;
    const std::size_t i = nextUnread();
    if (!parseInteger(tokens_[i], value)) {
      if (out.size() >= atLeast) break;
      expected(i, name, integerExpectation(tokens_[i]));
    }
    used_[i] = true;
    last_ = i;
    if (out.empty()) record(name, i);
    out.push_back(value);
  }
  if (out.size() < atLeast) {
    expected(
        nextUnread(), name,
        "expected at least " + std::to_string(atLeast) + " integer" + (atLeast > 1 ? "s" : ""));
  }
  return out;
}

std::vector<double> ArgReader::reals(std::string_view name, std::size_t atLeast) {
  std::vector<double> out;
  while (hasPositional()) {
    double value = 0.0;
    const std::size_t i = nextUnread();
    if (!parseReal(tokens_[i], value)) {
      if (out.size() >= atLeast) break;
      expected(i, name, "expected a number");
    }
    used_[i] = true;
    last_ = i;
    if (out.empty()) record(name, i);
    out.push_back(value);
  }
  if (out.size() < atLeast) {
    expected(nextUnread(), name,
             "expected at least " + std::to_string(atLeast) + " number" + (atLeast > 1 ? "s" : ""));
  }
  return out;
}

std::vector<double> ArgReader::reals(std::string_view name, std::size_t count, bool /*exact*/) {
  std::vector<double> out;
  out.reserve(count);
  for (std::size_t k = 0; k < count; ++k) out.push_back(real(name));
  return out;
}

std::size_t ArgReader::findKey(std::string_view key) const {
  for (std::size_t i = 0; i < tokens_.size(); ++i)
    if (!used_[i] && text(i) == key) return i;
  return kNone;
}

bool ArgReader::flag(std::string_view key) {
  const std::size_t i = findKey(key);
  if (i == kNone) return false;
  used_[i] = true;
  return true;
}

std::optional<double> ArgReader::optionalOption(std::string_view key) {
  const std::size_t i = findKey(key);
  if (i == kNone) return std::nullopt;
  used_[i] = true;
  double value = 0.0;
  if (i + 1 >= tokens_.size() || used_[i + 1] || !parseReal(tokens_[i + 1], value))
    expected(i + 1, key, "expected a number after " + std::string(key));
  used_[i + 1] = true;
  record(key, i + 1);
  return value;
}

double ArgReader::option(std::string_view key, double fallback) {
  return optionalOption(key).value_or(fallback);
}

int ArgReader::option(std::string_view key, int fallback) {
  const std::size_t i = findKey(key);
  if (i == kNone) return fallback;
  used_[i] = true;
  int value = 0;
  if (i + 1 >= tokens_.size() || used_[i + 1] || !parseInteger(tokens_[i + 1], value))
    expected(i + 1, key, "expected an integer after " + std::string(key));
  used_[i + 1] = true;
  record(key, i + 1);
  return value;
}

std::optional<std::string> ArgReader::optionalWordOption(std::string_view key) {
  const std::size_t i = findKey(key);
  if (i == kNone) return std::nullopt;
  used_[i] = true;
  if (i + 1 >= tokens_.size() || used_[i + 1])
    expected(i + 1, key, "expected a value after " + std::string(key));
  used_[i + 1] = true;
  record(key, i + 1);
  return std::string(text(i + 1));
}

std::string ArgReader::option(std::string_view key, const std::string& fallback) {
  return optionalWordOption(key).value_or(fallback);
}

double ArgReader::realAfterOption(std::string_view key, std::string_view name) {
  const std::size_t read = positionOf(key);
  assert(read != 0 && "realAfterOption needs the option's value read first");
  const std::size_t j = read + 1;
  double value = 0.0;
  if (j >= tokens_.size() || used_[j] || !parseReal(tokens_[j], value))
    expected(j, name,
             "expected a number after " + std::string(key) + " " + std::string(text(read)));
  used_[j] = true;
  record(name, j);
  return value;
}

std::vector<double> ArgReader::realsAfterOption(std::string_view key,
                                                std::initializer_list<std::string_view> names) {
  const std::size_t read = positionOf(key);
  assert(read != 0 && "realsAfterOption needs the option's value read first");
  std::string all;
  for (std::string_view name : names) {
    if (!all.empty()) all.push_back(' ');
    all.append(name);
  }
  std::vector<double> out;
  out.reserve(names.size());
  std::size_t j = read + 1;
  for (std::string_view name : names) {
    double value = 0.0;
    if (j >= tokens_.size() || used_[j] || !parseReal(tokens_[j], value))
      expected(j, name,
               "expected a number after " + std::string(key) + " " + std::string(text(read)) +
                   " (" + all + ")");
    used_[j] = true;
    record(name, j);
    out.push_back(value);
    ++j;
  }
  return out;
}

std::optional<std::vector<double>> ArgReader::optionReals(std::string_view key, std::size_t n) {
  const std::size_t i = findKey(key);
  if (i == kNone) return std::nullopt;
  used_[i] = true;
  record(key, i + 1);
  std::vector<double> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t j = i + 1 + k;
    if (j >= tokens_.size() || used_[j] || !parseReal(tokens_[j], out[k]))
      expected(j, key, "expected " + std::to_string(n) + " numbers after " + std::string(key));
    used_[j] = true;
  }
  return out;
}

std::optional<std::vector<double>> ArgReader::optionRealList(std::string_view key) {
  const std::size_t i = findKey(key);
  if (i == kNone) return std::nullopt;
  used_[i] = true;
  record(key, i + 1);
  std::vector<double> out;
  double value = 0.0;
  for (std::size_t j = i + 1; j < tokens_.size() && !used_[j] && parseReal(tokens_[j], value);
       ++j) {
    used_[j] = true;
    out.push_back(value);
  }
  if (out.empty()) expected(i + 1, key, "expected numbers after " + std::string(key));
  return out;
}

std::optional<std::vector<int>> ArgReader::optionIntegerList(std::string_view key) {
  const std::size_t i = findKey(key);
  if (i == kNone) return std::nullopt;
  used_[i] = true;
  record(key, i + 1);
  std::vector<int> out;
  int value = 0;
  for (std::size_t j = i + 1; j < tokens_.size() && !used_[j] && parseInteger(tokens_[j], value);
       ++j) {
    used_[j] = true;
    out.push_back(value);
  }
  if (out.empty()) expected(i + 1, key, "expected integers after " + std::string(key));
  return out;
}

std::optional<std::pair<int, int>> ArgReader::optionTagRange(std::string_view key) {
  const std::size_t i = findKey(key);
  if (i == kNone) return std::nullopt;
  used_[i] = true;
  record(key, i + 1);
  int ends[2] = {0, 0};
  for (std::size_t k = 0; k < 2; ++k) {
    const std::size_t j = i + 1 + k;
    if (j >= tokens_.size() || used_[j] || !parseInteger(tokens_[j], ends[k]))
      expected(j, key,
               integerExpectation(j < tokens_.size() ? tokens_[j] : nullptr) + " (" +
                   std::string(k == 0 ? "first" : "last") + " tag of " + std::string(key) + ")");
    used_[j] = true;
  }
  if (ends[0] > ends[1])
    expected(i + 2, key, "expected a last tag not below the first " + std::to_string(ends[0]));
  return std::pair{ends[0], ends[1]};
}

void ArgReader::finish() const {
  const std::size_t i = nextUnread();
  if (i < tokens_.size()) {
    fail(i, "extra", "unexpected argument \"" + std::string(text(i)) + "\"");
  }
}

}  // namespace dabs::tcl
