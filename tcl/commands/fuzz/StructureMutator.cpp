// SPDX-License-Identifier: MIT
#include "tcl/commands/fuzz/StructureMutator.h"

#include <tcl.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <set>
#include <utility>

namespace dabs::tcl::fuzz {

namespace {

// Values of each kind a slot may be given. Most are the edges the parsers must refuse or handle:
// 32-bit limits and beyond, octal and hexadecimal forms Tcl reads, NaN and infinities in the
// spellings Tcl accepts, denormals, blank words and lists where one word is expected.
constexpr std::array kIntegers{"0",           "1",           "2",          "3",
                               "-1",          "100",         "2147483647", "2147483648",
                               "-2147483648", "-2147483649", "4294967296", "99999999999999999999",
                               "007",         "0x10",        "+1",         "1000000"};
constexpr std::array kReals{"0.0",   "-0.0", "1e-320", "4.9e-324", "1e308", "-1e308",
                            "1e309", "NaN",  "nan",    "-NaN",     "Inf",   "-Inf",
                            "inf",   "1.5",  "-2.5",   "1e-12",    "0.5",   "1e20"};
constexpr std::array kBlanks{"", " ", "  ", "\t", "\n", "{}", " {} "};
constexpr std::array kLists{"1 2 3",
                            "Lobatto 1 3",
                            "HingeRadau 1 0.1 1 0.1 1",
                            "1 {2 3}",
                            "{} {}",
                            "a b",
                            "1.0 NaN",
                            "  1  ",
                            "Linear 1",
                            "Path -dt 0.1 -values {1 2}",
                            "-1 -2",
                            "1 2 3 4 5 6 7 8 9 10"};
constexpr std::array kWords{"x",  "{", "}", "\"", "\\",  "$x", "[",  ";",  "-",
                            "--", "+", "e", ".",  "1,5", "1e", "0x", "-e", "é"};

// Kinds a slot may be turned into, in the proportions they are drawn.
constexpr std::array kKinds{Kind::Integer, Kind::Real,  Kind::Real,  Kind::Option,
                            Kind::List,    Kind::Blank, Kind::Blank, Kind::Word};

bool isBlank(std::string_view w) {
  return std::all_of(w.begin(), w.end(), [](char c) { return std::isspace(c) != 0; });
}

// True when `words` is a command with a type word second (element, pattern, ...): templates of
// the same command and type are the ones to borrow slots from.
bool sameCommand(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  if (a.empty() || b.empty() || a[0] != b[0]) return false;
  if (a.size() < 2 || b.size() < 2) return true;
  const bool typed = kindOf(a[1]) == Kind::Word;
  return !typed || a[1] == b[1];
}

}  // namespace

Kind kindOf(std::string_view word) {
  if (isBlank(word)) return Kind::Blank;
  const std::string w(word);
  char* end = nullptr;
  (void)std::strtoll(w.c_str(), &end, 10);
  if (*end == '\0') return Kind::Integer;
  (void)std::strtod(w.c_str(), &end);
  if (*end == '\0') return Kind::Real;
  if (w.size() > 1 && w[0] == '-' && std::isalpha(static_cast<unsigned char>(w[1])) != 0)
    return Kind::Option;
  if (w.find_first_of(" \t\n") != std::string::npos) return Kind::List;
  return Kind::Word;
}

Grammar Grammar::parse(std::string_view text) {
  Grammar g;
  std::string section;
  std::set<std::string> options, types;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string line(text.substr(start, end - start));
    start = end + 1;
    if (line.empty() || line[0] == '#') continue;
    if (line[0] == '%') {
      section = line.substr(1);
      continue;
    }
    if (section == "prelude") g.prelude += line + "\n";
    if (section == "tail") g.tail += line + "\n";
    if (section != "command") continue;
    int n = 0;
    const char** items = nullptr;
    if (Tcl_SplitList(nullptr, line.c_str(), &n, &items) != TCL_OK) continue;
    std::vector<std::string> words(items, items + n);
    Tcl_Free(reinterpret_cast<char*>(items));
    if (words.empty()) continue;
    for (const std::string& w : words)
      if (kindOf(w) == Kind::Option) options.insert(w);
    if (words.size() > 1 && kindOf(words[1]) == Kind::Word) types.insert(words[1]);
    g.templates.push_back(std::move(words));
  }
  g.options.assign(options.begin(), options.end());
  g.typeWords.assign(types.begin(), types.end());
  return g;
}

StructureMutator::StructureMutator(Grammar grammar) : grammar_(std::move(grammar)) {}

std::vector<StructureMutator::Command> StructureMutator::split(std::string_view script) {
  std::vector<Command> commands;
  std::string text;
  std::size_t start = 0;
  // One complete command at a time, as the harness runs them.
  while (start < script.size()) {
    std::size_t end = script.find('\n', start);
    end = end == std::string_view::npos ? script.size() : end + 1;
    text.append(script.substr(start, end - start));
    start = end;
    if (!Tcl_CommandComplete(text.c_str()) && start < script.size()) continue;
    while (!text.empty() && text.back() == '\n') text.pop_back();
    Command c;
    c.text = text;
    int n = 0;
    const char** items = nullptr;
    // A comment, or a command with ';' separators or substitutions, is kept as it is: splitting
    // it as a list would change what it means.
    const bool plain = text.find_first_of(";$[") == std::string::npos &&
                       text.find_first_not_of(" \t") != std::string::npos &&
                       text[text.find_first_not_of(" \t")] != '#';
    if (plain && Tcl_SplitList(nullptr, text.c_str(), &n, &items) == TCL_OK) {
      c.words.assign(items, items + n);
      Tcl_Free(reinterpret_cast<char*>(items));
      c.parsed = !c.words.empty();
    }
    commands.push_back(std::move(c));
    text.clear();
  }
  return commands;
}

std::string StructureMutator::join(const std::vector<Command>& commands) {
  std::string out;
  std::vector<const char*> argv;
  for (const Command& c : commands) {
    if (!c.parsed) {
      out += c.text + "\n";
      continue;
    }
    argv.clear();
    for (const std::string& w : c.words) argv.push_back(w.c_str());
    // Tcl_Merge quotes each word so that it reads back as the same word (a blank word as {  }).
    char* merged = Tcl_Merge(static_cast<int>(argv.size()), argv.data());
    out += merged;
    out += "\n";
    Tcl_Free(merged);
  }
  return out;
}

std::string StructureMutator::valueOfKind(Kind kind) {
  auto pick = [this](const auto& pool) -> std::string {
    return pool[std::uniform_int_distribution<std::size_t>(0, pool.size() - 1)(rng_)];
  };
  switch (kind) {
    case Kind::Integer: return pick(kIntegers);
    case Kind::Real: return pick(kReals);
    case Kind::Option:
      return grammar_.options.empty() || rng_() % 8 == 0 ? std::string("-x")
                                                         : pick(grammar_.options);
    case Kind::List: return pick(kLists);
    case Kind::Blank: return pick(kBlanks);
    case Kind::Word:
      if (rng_() % 3 == 0 || grammar_.typeWords.empty()) return pick(kWords);
      return pick(grammar_.typeWords);
  }
  return {};
}

const std::vector<std::string>* StructureMutator::templateLike(
    const std::vector<std::string>& words) {
  std::vector<const std::vector<std::string>*> like;
  for (const auto& t : grammar_.templates)
    if (sameCommand(words, t)) like.push_back(&t);
  if (like.empty()) return nullptr;
  return like[std::uniform_int_distribution<std::size_t>(0, like.size() - 1)(rng_)];
}

bool StructureMutator::mutateWords(std::vector<std::string>& words, bool anyWord) {
  if (words.empty()) return false;
  const std::size_t first = anyWord || words.size() == 1 ? 0 : 1;
  auto slot = [&] {
    return std::uniform_int_distribution<std::size_t>(first, words.size() - 1)(rng_);
  };
  switch (rng_() % 10) {
    case 0:
    case 1:
    case 2:
    case 3: {  // a value of another kind
      const std::size_t i = slot();
      const Kind now = kindOf(words[i]);
      Kind to = now;
      for (int tries = 0; to == now && tries < 8; ++tries)
        to = kKinds[std::uniform_int_distribution<std::size_t>(0, kKinds.size() - 1)(rng_)];
      words[i] = valueOfKind(to);
      return true;
    }
    case 4: {  // a slot of another template of the same command (a valid value in its place)
      const auto* t = templateLike(words);
      if (t == nullptr || t->size() <= first) return false;
      const std::size_t i = std::uniform_int_distribution<std::size_t>(first, t->size() - 1)(rng_);
      if (i < words.size())
        words[i] = (*t)[i];
      else
        words.insert(words.end(), t->begin() + static_cast<std::ptrdiff_t>(words.size()),
                     t->begin() + static_cast<std::ptrdiff_t>(i) + 1);
      return true;
    }
    case 5: {  // an option repeated with its value, or a new option and value at the end
      std::vector<std::size_t> at;
      for (std::size_t i = 1; i < words.size(); ++i)
        if (kindOf(words[i]) == Kind::Option) at.push_back(i);
      if (at.empty() || rng_() % 3 == 0) {
        words.push_back(valueOfKind(Kind::Option));
        words.push_back(valueOfKind(kKinds[rng_() % kKinds.size()]));
        return true;
      }
      const std::size_t i = at[rng_() % at.size()];
      const std::size_t n = std::min<std::size_t>(words.size() - i, 1 + rng_() % 3);
      std::vector<std::string> copy(words.begin() + static_cast<std::ptrdiff_t>(i),
                                    words.begin() + static_cast<std::ptrdiff_t>(i + n));
      words.insert(words.end(), copy.begin(), copy.end());
      return true;
    }
    case 6: {  // words grouped into one list word, or a list spread into its words
      const std::size_t i = slot();
      int n = 0;
      const char** items = nullptr;
      if (kindOf(words[i]) == Kind::List &&
          Tcl_SplitList(nullptr, words[i].c_str(), &n, &items) == TCL_OK) {
        std::vector<std::string> spread(items, items + n);
        Tcl_Free(reinterpret_cast<char*>(items));
        words.erase(words.begin() + static_cast<std::ptrdiff_t>(i));
        words.insert(words.begin() + static_cast<std::ptrdiff_t>(i), spread.begin(), spread.end());
        return true;
      }
      const std::size_t n2 = std::min<std::size_t>(words.size() - i, 1 + rng_() % 4);
      std::string list;
      for (std::size_t k = i; k < i + n2; ++k) list += (k == i ? "" : " ") + words[k];
      words.erase(words.begin() + static_cast<std::ptrdiff_t>(i),
                  words.begin() + static_cast<std::ptrdiff_t>(i + n2));
      words.insert(words.begin() + static_cast<std::ptrdiff_t>(i), list);
      return true;
    }
    case 7: {  // a word deleted, or the command cut short
      const std::size_t i = slot();
      if (rng_() % 2 == 0)
        words.erase(words.begin() + static_cast<std::ptrdiff_t>(i));
      else
        words.resize(std::max<std::size_t>(i, 1));
      return true;
    }
    case 8: {  // a word inside a script body (pattern Plain ... {load ...}, section Fiber {...})
      std::vector<std::size_t> bodies;
      for (std::size_t i = first; i < words.size(); ++i)
        if (words[i].find_first_of(" \n") != std::string::npos) bodies.push_back(i);
      if (bodies.empty() || depth_ > 2) return false;
      std::string& body = words[bodies[rng_() % bodies.size()]];
      ++depth_;
      body = mutate(body, static_cast<unsigned>(rng_()));
      --depth_;
      return true;
    }
    default: {  // a slot copied from elsewhere in the command, or a word inserted
      const std::size_t i = slot();
      if (rng_() % 2 == 0) {
        words[i] = words[slot()];
      } else {
        words.insert(words.begin() + static_cast<std::ptrdiff_t>(i),
                     valueOfKind(kKinds[rng_() % kKinds.size()]));
      }
      return true;
    }
  }
}

std::string StructureMutator::generate(unsigned seed) {
  rng_.seed(seed);
  if (grammar_.templates.empty()) return grammar_.prelude;
  std::vector<std::string> words = grammar_.templates[std::uniform_int_distribution<std::size_t>(
      0, grammar_.templates.size() - 1)(rng_)];
  // The command as the grammar has it is valid or close to it; the slot changed is the test.
  if (rng_() % 4 != 0) (void)mutateWords(words, false);
  std::vector<Command> commands(1);
  commands[0].words = std::move(words);
  commands[0].parsed = true;
  std::string out = grammar_.prelude + join(commands);
  if (rng_() % 2 == 0) out += grammar_.tail;
  return out;
}

std::string StructureMutator::mutate(std::string_view script, unsigned seed) {
  if (depth_ == 0) rng_.seed(seed);
  std::vector<Command> commands = split(script);
  std::vector<std::size_t> parsed;
  for (std::size_t i = 0; i < commands.size(); ++i)
    if (commands[i].parsed) parsed.push_back(i);
  if (depth_ == 0 && (parsed.empty() || rng_() % 16 == 0)) return generate(seed);
  const unsigned what = rng_() % 16;
  if (!grammar_.templates.empty() && (parsed.empty() || what < 2)) {
    // A template inserted, or put in place of a command (the scripts' model around it).
    Command c;
    c.words = grammar_.templates[std::uniform_int_distribution<std::size_t>(
        0, grammar_.templates.size() - 1)(rng_)];
    c.parsed = true;
    if (rng_() % 2 == 0) (void)mutateWords(c.words, false);
    const std::size_t at = std::uniform_int_distribution<std::size_t>(0, commands.size())(rng_);
    if (what == 0 && at < commands.size())
      commands[at] = std::move(c);
    else
      commands.insert(commands.begin() + static_cast<std::ptrdiff_t>(at), std::move(c));
    return join(commands);
  }
  if (parsed.empty()) return std::string(script);
  // The later of two draws: the command under test usually follows its model.
  std::uniform_int_distribution<std::size_t> draw(0, parsed.size() - 1);
  const std::size_t pick = parsed[std::max(draw(rng_), draw(rng_))];
  if (what == 2 && commands.size() > 1) {  // a command run twice
    commands.insert(commands.begin() + static_cast<std::ptrdiff_t>(pick), commands[pick]);
    return join(commands);
  }
  if (what == 3 && commands.size() > 1) {  // a command left out
    commands.erase(commands.begin() + static_cast<std::ptrdiff_t>(pick));
    return join(commands);
  }
  for (int tries = 0; tries < 4; ++tries)
    if (mutateWords(commands[pick].words, what == 4)) break;
  return join(commands);
}

}  // namespace dabs::tcl::fuzz
