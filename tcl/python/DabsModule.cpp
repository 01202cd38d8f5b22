// SPDX-License-Identifier: MIT
// The Python module `dabs` (OpenSeesPy-style): `dabs.node(1, 0.0, 0.0)`, `dabs.analyze(10, 0.01)`.
// The module owns one Tcl interpreter with the DABS commands registered exactly as the Tcl package
// registers them, and each Python function calls its Tcl command object directly (Tcl_EvalObjv,
// no script text), so a Python model and its Tcl twin run the same code on the same arguments.
// What Python adds: argument and result conversion, the `section Fiber` block written as a call
// sequence, and dabs.OpenSeesError for failed commands. See README "Python".
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <structmember.h>
#include <tcl.h>

#include <cstring>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "tcl/commands/CommandTable.h"
#include "tcl/parallel/ParallelCommands.h"

namespace {

/// How a command's Tcl result becomes a Python value (OpenSeesPy's conventions).
enum class ResultKind {
  Generic,     ///< int/float/list by the Tcl object's type; a non-numeric string stays a str
  Vector,      ///< nodeDisp & co: a list of floats for the whole vector, a float for one dof
  FloatList,   ///< eigen, eleResponse: always a list of floats (an int status code stays an int)
  IntList,     ///< getNodeTags, getEleTags, eleNodes, pounding, getNDM: always a list of ints
  Float,       ///< getTime, getLoadFactor
  Dictionary,  ///< analysisStatistics, contactStepping: a dict of numbers
  String,      ///< version
};

struct CommandKind {
  std::string_view name;
  ResultKind kind;
};

// Commands whose result is not read well by the generic rule. Any command missing here (a new one
// in the table) still works: its result is converted by the Tcl object's type.
constexpr CommandKind kResultKinds[] = {
    {"nodeDisp", ResultKind::Vector},
    {"nodeVel", ResultKind::Vector},
    {"nodeAccel", ResultKind::Vector},
    {"nodeReaction", ResultKind::Vector},
    {"nodeCoord", ResultKind::Vector},
    {"nodeMass", ResultKind::Vector},
    {"nodeEigenvector", ResultKind::Vector},
    {"eleForce", ResultKind::Vector},
    {"eigen", ResultKind::FloatList},
    {"eleResponse", ResultKind::FloatList},
    {"getNodeTags", ResultKind::IntList},
    {"getEleTags", ResultKind::IntList},
    {"eleNodes", ResultKind::IntList},
    {"pounding", ResultKind::IntList},
    {"getNDM", ResultKind::IntList},  // OpenSeesPy returns [ndm], [ndf]
    {"getNDF", ResultKind::IntList},
    {"getTime", ResultKind::Float},
    {"getLoadFactor", ResultKind::Float},
    {"analysisStatistics", ResultKind::Dictionary},
    {"contactStepping", ResultKind::Dictionary},
    {"version", ResultKind::String},
};

ResultKind resultKind(std::string_view name) {
  for (const CommandKind& k : kResultKinds)
    if (k.name == name) return k.kind;
  return ResultKind::Generic;
}

// Options whose value Tcl reads as one list word (a Python list there stays one Tcl list instead
// of being spread into words): the number of list arguments after the flag.
struct ListOption {
  std::string_view command;
  std::string_view flag;
  int lists;
};
constexpr ListOption kListOptions[] = {
    {"timeSeries", "-values", 1},   {"timeSeries", "-time", 1}, {"pounding", "-side1", 2},
    {"pounding", "-side2", 2},      {"recorder", "-plots", 1},  {"recorder", "-beamSection", 1},
    {"recorder", "-bearingPad", 1}, {"recorder", "-block", 1},  {"recorder", "-gaps", 1},
};

// Commands that read their arguments as Tcl values of their own (a variable's value, a job list,
// a script): Python lists are passed as Tcl lists, never spread.
constexpr std::string_view kNoSpread[] = {"pset", "ensemble", "contactStepping"};

// The commands that make up a `section Fiber` body in Tcl.
constexpr std::string_view kSectionMembers[] = {"patch", "layer", "fiber"};

template <std::size_t N>
bool contains(const std::string_view (&list)[N], std::string_view name) {
  for (std::string_view s : list)
    if (s == name) return true;
  return false;
}

/// Per-module state (PEP 3121): everything the module needs lives here, nothing in globals.
struct State {
  Tcl_Interp* interp = nullptr;
  PyObject* error = nullptr;        ///< dabs.OpenSeesError
  PyObject* commandType = nullptr;  ///< the type of the command objects
  unsigned long thread = 0;         ///< the thread that imported the module owns the interpreter
  /// An open `section Fiber` block: the section command's words (a Tcl list) and its body so far
  /// (the patch/layer/fiber calls, one Tcl list per line). Null when no block is open.
  Tcl_Obj* blockHead = nullptr;
  Tcl_Obj* blockBody = nullptr;
};

State* stateOf(PyObject* module) { return static_cast<State*>(PyModule_GetState(module)); }

/// One Python function per Tcl command, e.g. dabs.nodeDisp.
struct Command {
  PyObject_HEAD vectorcallfunc vectorcall;
  Tcl_Obj* name;                         ///< the command word; Tcl caches the command lookup in it
  const dabs::tcl::CommandEntry* entry;  ///< the table row: name and usage (static storage)
  ResultKind kind;
  bool sectionMember;
  bool noSpread;
};

/// Holds references to the Tcl words of one call and releases them on every path.
class Words {
 public:
  Words() = default;
  Words(const Words&) = delete;
  Words& operator=(const Words&) = delete;
  ~Words() {
    Tcl_Obj** w = data();
    for (std::size_t i = 0; i < size_; ++i) Tcl_DecrRefCount(w[i]);
  }
  void push(Tcl_Obj* o) {
    Tcl_IncrRefCount(o);
    if (words_.empty() && size_ < kInline) {
      inline_[size_++] = o;
      return;
    }
    if (words_.empty()) words_.assign(inline_, inline_ + size_);
    words_.push_back(o);
    ++size_;
  }
  int size() const { return static_cast<int>(size_); }
  Tcl_Obj** data() { return words_.empty() ? inline_ : words_.data(); }

 private:
  // Most commands have a few words: those stay on the stack (no allocation per call).
  static constexpr std::size_t kInline = 24;
  Tcl_Obj* inline_[kInline] = {};
  std::size_t size_ = 0;
  std::vector<Tcl_Obj*> words_;
};

PyObject* raise(State* st, const std::string& message) {
  // After the module was cleared at interpreter shutdown there is no OpenSeesError left to raise.
  PyErr_SetString(st != nullptr && st->error != nullptr ? st->error : PyExc_RuntimeError,
                  message.c_str());
  return nullptr;
}

// Python value -> Tcl value. Integers stay integers and floats doubles, so no digit is lost (Tcl
// prints a double with the shortest text that reads back to it, should a command need the text).
// A list or tuple becomes a Tcl list. Returns null with a Python error set on a value Tcl has no
// form for.
/// Where an argument stands, for error messages (built only when one is needed).
struct ArgPlace {
  std::string_view command;
  Py_ssize_t position;  ///< 1-based, among the Python arguments
  std::string text() const {
    return std::string(command) + ": argument " + std::to_string(position);
  }
};

/// Lists, tuples and other sequences of values (a numpy array, a range), but not text.
bool isSequence(PyObject* o) {
  if (PyList_Check(o) || PyTuple_Check(o)) return true;
  return PySequence_Check(o) && !PyUnicode_Check(o) && !PyBytes_Check(o) && !PyByteArray_Check(o) &&
         !PyIndex_Check(o);
}

Tcl_Obj* toTcl(State* st, PyObject* o, const ArgPlace& where) {
  if (PyFloat_Check(o)) return Tcl_NewDoubleObj(PyFloat_AS_DOUBLE(o));
  if (PyLong_Check(o)) {
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(o, &overflow);
    if (overflow != 0) {
      raise(st, where.text() + ": integer out of range");
      return nullptr;
    }
    return Tcl_NewWideIntObj(static_cast<Tcl_WideInt>(v));
  }
  if (PyUnicode_Check(o)) {
    Py_ssize_t size = 0;
    const char* text = PyUnicode_AsUTF8AndSize(o, &size);
    if (text == nullptr) return nullptr;
    return Tcl_NewStringObj(text, static_cast<int>(size));
  }
  if (isSequence(o)) {
    // A tuple copy: converting an element may run Python code (__float__) that changes a list.
    PyObject* seq = PySequence_Tuple(o);
    if (seq == nullptr) return nullptr;
    // A list that holds itself would recurse for ever.
    if (Py_EnterRecursiveCall(" while converting a nested list for Tcl") != 0) {
      Py_DECREF(seq);
      return nullptr;
    }
    // Returned with no reference held (as Tcl_New*Obj returns); freed here only on failure.
    Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
    const Py_ssize_t n = PyTuple_GET_SIZE(seq);
    for (Py_ssize_t i = 0; i < n; ++i) {
      Tcl_Obj* item = toTcl(st, PyTuple_GET_ITEM(seq, i), where);
      if (item == nullptr) {
        Py_LeaveRecursiveCall();
        Py_DECREF(seq);
        Tcl_IncrRefCount(list);
        Tcl_DecrRefCount(list);
        return nullptr;
      }
      Tcl_ListObjAppendElement(nullptr, list, item);
    }
    Py_LeaveRecursiveCall();
    Py_DECREF(seq);
    return list;
  }
  // numpy scalars and other number types: integers by __index__, reals by __float__.
  if (PyIndex_Check(o)) {
    PyObject* i = PyNumber_Index(o);
    if (i == nullptr) return nullptr;
    Tcl_Obj* t = toTcl(st, i, where);
    Py_DECREF(i);
    return t;
  }
  if (Py_TYPE(o)->tp_as_number != nullptr && Py_TYPE(o)->tp_as_number->nb_float != nullptr) {
    const double v = PyFloat_AsDouble(o);
    if (v == -1.0 && PyErr_Occurred()) return nullptr;
    return Tcl_NewDoubleObj(v);
  }
  raise(st, where.text() + ": expected a number, a string or a list of them, got " +
                Py_TYPE(o)->tp_name);
  return nullptr;
}

bool isTclType(Tcl_Obj* o, const char* name) {
  return o->typePtr != nullptr && std::strcmp(o->typePtr->name, name) == 0;
}

// A Tcl value as a number when it is one: an int, else a float; null (no error) when not a number.
PyObject* number(Tcl_Obj* o) {
  if (isTclType(o, "double")) return PyFloat_FromDouble(o->internalRep.doubleValue);
  Tcl_WideInt w = 0;
  if (Tcl_GetWideIntFromObj(nullptr, o, &w) == TCL_OK)
    return PyLong_FromLongLong(static_cast<long long>(w));
  double d = 0.0;
  if (Tcl_GetDoubleFromObj(nullptr, o, &d) == TCL_OK) return PyFloat_FromDouble(d);
  return nullptr;
}

PyObject* text(Tcl_Obj* o) {
  int size = 0;
  const char* s = Tcl_GetStringFromObj(o, &size);
  return PyUnicode_DecodeUTF8(s, size, "replace");
}

// A Tcl list as a Python list, each element as a number when it is one (`asFloat`: every number a
// float; `asInt`: every element an int). Null with no error when `o` is not a list of numbers.
PyObject* numberList(Tcl_Obj* o, bool asFloat, bool asInt) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(nullptr, o, &n, &items) != TCL_OK) return nullptr;
  PyObject* list = PyList_New(n);
  if (list == nullptr) return nullptr;
  for (int i = 0; i < n; ++i) {
    PyObject* v = nullptr;
    if (asFloat) {
      double d = 0.0;
      if (Tcl_GetDoubleFromObj(nullptr, items[i], &d) == TCL_OK) v = PyFloat_FromDouble(d);
    } else if (asInt) {
      Tcl_WideInt w = 0;
      if (Tcl_GetWideIntFromObj(nullptr, items[i], &w) == TCL_OK)
        v = PyLong_FromLongLong(static_cast<long long>(w));
    } else {
      v = number(items[i]);
    }
    if (v == nullptr) {
      Py_DECREF(list);
      return nullptr;
    }
    PyList_SET_ITEM(list, i, v);
  }
  return list;
}

// Tcl result -> Python value by the command's convention; an empty result is None.
PyObject* fromTcl(Tcl_Obj* o, ResultKind kind) {
  // Numbers are never empty; asking another value for its length may build its text.
  int size = 1;
  if (!isTclType(o, "double") && !isTclType(o, "int")) {
    if (isTclType(o, "list"))
      Tcl_ListObjLength(nullptr, o, &size);
    else
      Tcl_GetStringFromObj(o, &size);
  }
  if (size == 0) {
    // No nodes, no elements: an empty list where a list is expected, else None.
    if (kind == ResultKind::IntList || kind == ResultKind::FloatList) return PyList_New(0);
    Py_RETURN_NONE;
  }
  if (kind == ResultKind::String) return text(o);
  if (kind == ResultKind::Dictionary) {
    int n = 0;
    Tcl_Obj** items = nullptr;
    if (Tcl_ListObjGetElements(nullptr, o, &n, &items) == TCL_OK && n % 2 == 0) {
      PyObject* dict = PyDict_New();
      for (int i = 0; dict != nullptr && i < n; i += 2) {
        PyObject* key = text(items[i]);
        PyObject* value = number(items[i + 1]);
        if (value == nullptr && !PyErr_Occurred()) value = text(items[i + 1]);
        if (key == nullptr || value == nullptr || PyDict_SetItem(dict, key, value) != 0)
          Py_CLEAR(dict);
        Py_XDECREF(key);
        Py_XDECREF(value);
      }
      if (dict != nullptr || PyErr_Occurred()) return dict;
    }
    return text(o);
  }
  const bool isList = isTclType(o, "list");
  if (kind == ResultKind::IntList) {
    if (PyObject* l = numberList(o, false, true)) return l;
  } else if (kind == ResultKind::FloatList || (kind == ResultKind::Vector && isList)) {
    // A status code (an int, not a list) from a failed eigen stays an int.
    if (isList || !isTclType(o, "int"))
      if (PyObject* l = numberList(o, true, false)) return l;
  } else if (kind == ResultKind::Float || kind == ResultKind::Vector) {
    double d = 0.0;
    if (Tcl_GetDoubleFromObj(nullptr, o, &d) == TCL_OK) return PyFloat_FromDouble(d);
  } else if (isList) {
    if (PyObject* l = numberList(o, false, false)) return l;
  }
  if (PyErr_Occurred()) return nullptr;
  if (PyObject* v = number(o)) return v;
  if (PyErr_Occurred()) return nullptr;
  // A string that is a list of two or more numbers (a result built as text) is a list.
  int n = 0;
  if (Tcl_ListObjLength(nullptr, o, &n) == TCL_OK && n > 1)
    if (PyObject* l = numberList(o, false, false)) return l;
  if (PyErr_Occurred()) return nullptr;
  return text(o);
}

bool ownerThread(State* st) {
  if (PyThread_get_thread_ident() == st->thread) return true;
  raise(st,
        "dabs: the model belongs to the thread that imported the module; call it from that "
        "thread only");
  return false;
}

// Runs one command (words already converted). `longRun` releases the GIL while Tcl works: no
// Python code runs inside a command and only the owning thread may enter, so nothing else touches
// the interpreter meanwhile.
int evalWords(State* st, Words& words, bool longRun) {
  if (!longRun) return Tcl_EvalObjv(st->interp, words.size(), words.data(), 0);
  PyThreadState* saved = PyEval_SaveThread();
  const int code = Tcl_EvalObjv(st->interp, words.size(), words.data(), 0);
  PyEval_RestoreThread(saved);
  return code;
}

// Python's sys.stdout and Tcl's stdout channel buffer on their own: flushing Python's before Tcl
// writes and Tcl's after keeps lines of `print(..)` and of `puts`/`printModel` in call order.
void flushPythonStdout() {
  PyObject* out = PySys_GetObject("stdout");  // borrowed
  if (out == nullptr || out == Py_None) return;
  PyObject* r = PyObject_CallMethod(out, "flush", nullptr);
  if (r == nullptr) PyErr_Clear();  // a closed or odd stdout is not the command's failure
  Py_XDECREF(r);
}

void flushTclStdout() {
  if (Tcl_Channel out = Tcl_GetStdChannel(TCL_STDOUT)) Tcl_Flush(out);
}

PyObject* tclError(State* st) {
  raise(st, Tcl_GetStringResult(st->interp));
  Tcl_ResetResult(st->interp);
  return nullptr;
}

// Closes an open `section Fiber` block: runs the section command with the collected calls as its
// body, as Tcl would have run `section Fiber tag .. { patch ..; layer .. }`. Returns false with
// OpenSeesError set when the section fails (the section is then not defined); the message is
// Tcl's, followed by which call closed the block, since that call raises it and does not run.
bool closeBlock(State* st, std::string_view closer) {
  if (st->blockHead == nullptr) return true;
  Tcl_Obj* head = st->blockHead;
  Tcl_Obj* body = st->blockBody;
  st->blockHead = nullptr;
  st->blockBody = nullptr;
  Words words;
  int n = 0;
  Tcl_Obj** items = nullptr;
  Tcl_ListObjGetElements(nullptr, head, &n, &items);
  for (int i = 0; i < n; ++i) words.push(items[i]);
  words.push(body);
  Tcl_DecrRefCount(head);
  Tcl_DecrRefCount(body);
  if (evalWords(st, words, false) != TCL_OK) {
    const std::string message = std::string(Tcl_GetStringResult(st->interp)) +
                                " (the section block was closed by the call of " +
                                std::string(closer) + ", which was not run)";
    Tcl_ResetResult(st->interp);
    raise(st, message);
    return false;
  }
  Tcl_ResetResult(st->interp);
  return true;
}

void dropBlock(State* st) {
  if (st->blockHead != nullptr) Tcl_DecrRefCount(st->blockHead);
  if (st->blockBody != nullptr) Tcl_DecrRefCount(st->blockBody);
  st->blockHead = st->blockBody = nullptr;
}

bool isWord(PyObject* o, std::string_view w) {
  if (!PyUnicode_Check(o)) return false;
  Py_ssize_t size = 0;
  const char* s = PyUnicode_AsUTF8AndSize(o, &size);
  if (s == nullptr) {
    PyErr_Clear();
    return false;
  }
  return std::string_view(s, static_cast<std::size_t>(size)) == w;
}

bool isListOptionFlag(std::string_view command, PyObject* o, int& lists) {
  for (const ListOption& opt : kListOptions)
    if (opt.command == command && isWord(o, opt.flag)) {
      lists = opt.lists;
      return true;
    }
  return false;
}

bool isNumber(PyObject* o) {
  if (PyFloat_Check(o) || PyLong_Check(o)) return true;
  if (PyUnicode_Check(o) || isSequence(o)) return false;
  return PyIndex_Check(o) ||
         (Py_TYPE(o)->tp_as_number != nullptr && Py_TYPE(o)->tp_as_number->nb_float != nullptr);
}

// Python arguments -> Tcl words. A list or tuple is spread into words, as OpenSeesPy reads
// `fix(1, [1, 1, 1])`, except where Tcl reads one list (kListOptions, kNoSpread); after
// `timeSeries .. -values`/`-time` numbers given one by one (OpenSeesPy's `'-values', *values`) are
// gathered into that list.
bool convertArgs(State* st, Command* c, PyObject* const* args, Py_ssize_t nargs, Words& words) {
  words.push(c->name);
  const std::string_view name = c->entry->name;
  int keepLists = 0;
  for (Py_ssize_t i = 0; i < nargs; ++i) {
    PyObject* a = args[i];
    const ArgPlace where{name, i + 1};
    if (name == "timeSeries" && (isWord(a, "-values") || isWord(a, "-time")) && i + 1 < nargs &&
        isNumber(args[i + 1])) {
      Tcl_Obj* flag = toTcl(st, a, where);
      if (flag == nullptr) return false;
      words.push(flag);
      Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
      words.push(list);
      for (; i + 1 < nargs && isNumber(args[i + 1]); ++i) {
        Tcl_Obj* v = toTcl(st, args[i + 1], where);
        if (v == nullptr) return false;
        Tcl_ListObjAppendElement(nullptr, list, v);
      }
      continue;
    }
    const bool spread = !c->noSpread && keepLists == 0 && isSequence(a);
    if (keepLists > 0) --keepLists;
    int lists = 0;
    if (isListOptionFlag(name, a, lists)) keepLists = lists;
    if (spread) {
      PyObject* seq = PySequence_Tuple(a);
      if (seq == nullptr) return false;
      const Py_ssize_t n = PyTuple_GET_SIZE(seq);
      for (Py_ssize_t k = 0; k < n; ++k) {
        Tcl_Obj* v = toTcl(st, PyTuple_GET_ITEM(seq, k), where);
        if (v == nullptr) {
          Py_DECREF(seq);
          return false;
        }
        words.push(v);
      }
      Py_DECREF(seq);
    } else {
      Tcl_Obj* v = toTcl(st, a, where);
      if (v == nullptr) return false;
      words.push(v);
    }
  }
  // OpenSeesPy's getTime is the exact time; Tcl's default format has 6 decimals.
  if (name == "getTime" && nargs == 0) words.push(Tcl_NewStringObj("%.17g", -1));
  // `pattern MultipleSupport tag` opens a pattern whose groundMotion/imposedMotion calls follow;
  // in Tcl the pattern stays current after its body, so an empty body and then the calls define
  // the same pattern.
  if (name == "pattern" && nargs == 2 &&
      (isWord(args[0], "MultipleSupport") || isWord(args[0], "MultiSupport") ||
       isWord(args[0], "MultipleSupportExcitation")))
    words.push(Tcl_NewObj());
  return true;
}

// Whether `section(...)` opens a block: a fiber section given without its body, i.e. nothing
// after the tag but its options (`-GJ GJ`, `-noCentroid`). A body given as a Tcl script string,
// as in Tcl, runs at once.
bool opensFiberBlock(PyObject* const* args, Py_ssize_t nargs) {
  if (nargs < 1 || !(isWord(args[0], "Fiber") || isWord(args[0], "fiberSec"))) return false;
  for (Py_ssize_t i = 2; i < nargs; ++i) {
    if (isWord(args[i], "-GJ"))
      ++i;
    else if (!isWord(args[i], "-noCentroid"))
      return false;
  }
  return true;
}

// A Tcl list of the words, as one line of a section body.
Tcl_Obj* lineOf(Words& words) { return Tcl_NewListObj(words.size(), words.data()); }

PyObject* commandCall(PyObject* self, PyObject* const* args, size_t nargsf, PyObject* kwnames) {
  auto* c = reinterpret_cast<Command*>(self);
  // The type was made for this module (PyType_FromModuleAndSpec): no reference cycle from the
  // functions back to the module is needed to find its state.
  auto* st = static_cast<State*>(PyType_GetModuleState(Py_TYPE(self)));
  if (st == nullptr || st->interp == nullptr) return raise(st, "dabs: the module was shut down");
  if (!ownerThread(st)) return nullptr;
  const std::string_view name = c->entry->name;
  if (kwnames != nullptr && PyTuple_GET_SIZE(kwnames) > 0)
    return raise(st, std::string(name) +
                         ": keyword arguments are not accepted (pass flags as strings, e.g. "
                         "'-mass', 1.0)");
  const Py_ssize_t nargs = PyVectorcall_NARGS(nargsf);
  Words words;
  if (!convertArgs(st, c, args, nargs, words)) return nullptr;

  if (c->sectionMember && st->blockHead != nullptr) {
    Tcl_Obj* line = lineOf(words);
    Tcl_IncrRefCount(line);
    Tcl_AppendObjToObj(st->blockBody, line);
    Tcl_AppendToObj(st->blockBody, "\n", 1);
    Tcl_DecrRefCount(line);
    Py_RETURN_NONE;
  }
  if (!closeBlock(st, name)) return nullptr;
  if (name == "section" && opensFiberBlock(args, nargs)) {
    // The section is defined when its block closes: at the next call that is not patch, layer or
    // fiber.
    st->blockHead = lineOf(words);
    Tcl_IncrRefCount(st->blockHead);
    st->blockBody = Tcl_NewObj();
    Tcl_IncrRefCount(st->blockBody);
    Py_RETURN_NONE;
  }
  const bool longRun = name == "analyze" || name == "eigen" || name == "ensemble";
  const bool writes = name == "print" || name == "printModel";
  if (writes) flushPythonStdout();
  const int code = evalWords(st, words, longRun);
  if (writes) flushTclStdout();
  if (code != TCL_OK) return tclError(st);
  PyObject* result = fromTcl(Tcl_GetObjResult(st->interp), c->kind);
  Tcl_ResetResult(st->interp);
  return result;
}

void commandDealloc(PyObject* self) {
  auto* c = reinterpret_cast<Command*>(self);
  PyTypeObject* type = Py_TYPE(self);
  if (c->name != nullptr) Tcl_DecrRefCount(c->name);
  type->tp_free(self);
  Py_DECREF(type);
}

PyObject* commandRepr(PyObject* self) {
  auto* c = reinterpret_cast<Command*>(self);
  const std::string name(c->entry->name);
  return PyUnicode_FromFormat("<dabs command %s>", name.c_str());
}

PyObject* fromView(std::string_view v) {
  return PyUnicode_FromStringAndSize(v.data(), static_cast<Py_ssize_t>(v.size()));
}

PyObject* commandGetName(PyObject* self, void*) {
  return fromView(reinterpret_cast<Command*>(self)->entry->name);
}

// The usage line is the help text: `help(dabs.node)` shows the Tcl syntax the arguments follow.
PyObject* commandGetDoc(PyObject* self, void*) {
  return fromView(reinterpret_cast<Command*>(self)->entry->usage);
}

PyMemberDef kCommandMembers[] = {
    {"__vectorcalloffset__", T_PYSSIZET, offsetof(Command, vectorcall), READONLY, nullptr},
    {nullptr, 0, 0, 0, nullptr},
};

PyGetSetDef kCommandGetSet[] = {
    {"__name__", commandGetName, nullptr, nullptr, nullptr},
    {"__doc__", commandGetDoc, nullptr, nullptr, nullptr},
    {nullptr, nullptr, nullptr, nullptr, nullptr},
};

PyType_Slot kCommandSlots[] = {
    {Py_tp_dealloc, reinterpret_cast<void*>(commandDealloc)},
    {Py_tp_call, reinterpret_cast<void*>(PyVectorcall_Call)},
    {Py_tp_repr, reinterpret_cast<void*>(commandRepr)},
    {Py_tp_members, kCommandMembers},
    {Py_tp_getset, kCommandGetSet},
    {0, nullptr},
};

PyType_Spec kCommandSpec = {"dabs.Command", sizeof(Command), 0,
                            Py_TPFLAGS_DEFAULT | Py_TPFLAGS_HAVE_VECTORCALL |
                                Py_TPFLAGS_DISALLOW_INSTANTIATION | Py_TPFLAGS_IMMUTABLETYPE,
                            kCommandSlots};

PyObject* makeCommand(State* st, const dabs::tcl::CommandEntry* entry) {
  auto* type = reinterpret_cast<PyTypeObject*>(st->commandType);
  auto* c = reinterpret_cast<Command*>(type->tp_alloc(type, 0));
  if (c == nullptr) return nullptr;
  c->vectorcall = commandCall;
  c->entry = entry;
  c->name = Tcl_NewStringObj(entry->name.data(), static_cast<int>(entry->name.size()));
  Tcl_IncrRefCount(c->name);
  c->kind = resultKind(entry->name);
  c->sectionMember = contains(kSectionMembers, entry->name);
  c->noSpread = contains(kNoSpread, entry->name);
  return reinterpret_cast<PyObject*>(c);
}

// dabs.tcl(script): evaluates Tcl in the module's interpreter at global level and returns its
// result as a string.
PyObject* tclEval(PyObject* module, PyObject* arg) {
  State* st = stateOf(module);
  if (st->interp == nullptr) return raise(st, "dabs: the module was shut down");
  if (!ownerThread(st)) return nullptr;
  if (!PyUnicode_Check(arg))
    return raise(
        st, std::string("tcl: argument 1 (script): expected a str, got ") + Py_TYPE(arg)->tp_name);
  Py_ssize_t size = 0;
  const char* script = PyUnicode_AsUTF8AndSize(arg, &size);
  if (script == nullptr) return nullptr;
  if (!closeBlock(st, "tcl")) return nullptr;
  Tcl_Obj* obj = Tcl_NewStringObj(script, static_cast<int>(size));
  Tcl_IncrRefCount(obj);
  flushPythonStdout();
  PyThreadState* saved = PyEval_SaveThread();
  int code = Tcl_EvalObjEx(st->interp, obj, TCL_EVAL_GLOBAL);
  PyEval_RestoreThread(saved);
  Tcl_DecrRefCount(obj);
  flushTclStdout();
  if (code == TCL_RETURN) code = TCL_OK;
  if (code != TCL_OK) return tclError(st);
  PyObject* result = text(Tcl_GetObjResult(st->interp));
  Tcl_ResetResult(st->interp);
  return result;
}

// Deletes the interpreter (which flushes and closes the recorders) before Python finalises.
void shutdownState(State* st) {
  if (st == nullptr || st->interp == nullptr) return;
  dropBlock(st);
  flushTclStdout();
  Tcl_DeleteInterp(st->interp);
  st->interp = nullptr;
}

PyObject* shutdown(PyObject* module, PyObject*) {
  shutdownState(stateOf(module));
  Py_RETURN_NONE;
}

PyMethodDef kModuleMethods[] = {
    {"tcl", tclEval, METH_O,
     "tcl(script) -> str: evaluates Tcl in the model's interpreter (every DABS command, `source`, "
     "variables) and returns the result as a string."},
    {"_shutdown", shutdown, METH_NOARGS,
     "Deletes the interpreter (closing the recorders); called at exit."},
    {nullptr, nullptr, 0, nullptr},
};

int moduleExec(PyObject* module) {
  State* st = stateOf(module);
  // Python zero-fills the state; an interpreter already there means the module was set up.
  if (st->interp != nullptr) return 0;
  new (st) State();
  st->thread = PyThread_get_thread_ident();
  st->error = PyErr_NewExceptionWithDoc(
      "dabs.OpenSeesError",
      "A DABS command failed; the message is the Tcl error naming the command and the argument. "
      "The model is as it was before the call.",
      PyExc_Exception, nullptr);
  if (st->error == nullptr) return -1;
  Py_INCREF(st->error);
  if (PyModule_AddObject(module, "OpenSeesError", st->error) != 0) {
    Py_DECREF(st->error);
    return -1;
  }
  st->commandType = PyType_FromModuleAndSpec(module, &kCommandSpec, nullptr);
  if (st->commandType == nullptr) return -1;

  Tcl_FindExecutable(nullptr);
  st->interp = Tcl_CreateInterp();
  // As a script run by `dabs` with no arguments sees them (bridge.tcl reads argc/argv).
  Tcl_SetVar2Ex(st->interp, "argv0", nullptr, Tcl_NewStringObj("dabs", -1), TCL_GLOBAL_ONLY);
  Tcl_SetVar2Ex(st->interp, "argc", nullptr, Tcl_NewIntObj(0), TCL_GLOBAL_ONLY);
  Tcl_SetVar2Ex(st->interp, "argv", nullptr, Tcl_NewObj(), TCL_GLOBAL_ONLY);
  Tcl_SetVar2Ex(st->interp, "tcl_interactive", nullptr, Tcl_NewIntObj(0), TCL_GLOBAL_ONLY);
  // The commands of the `dabs` program: the library's and the parallel ones.
  const std::span<const dabs::tcl::CommandEntry> parallel[] = {dabs::parallel::parallelCommands()};
  if (Tcl_Init(st->interp) != TCL_OK ||
      dabs::tcl::registerCommands(st->interp, parallel) != TCL_OK) {
    PyErr_Format(PyExc_ImportError, "dabs: cannot start the Tcl interpreter: %s",
                 Tcl_GetStringResult(st->interp));
    return -1;
  }
  Tcl_PkgProvide(st->interp, "dabs", DABS_VERSION);
  if (PyModule_AddStringConstant(module, "__version__", DABS_VERSION) != 0) return -1;

  // One function per row of the command table, so a new Tcl command appears here unedited.
  PyObject* names = PyList_New(0);
  if (names == nullptr) return -1;
  for (const dabs::tcl::CommandEntry* e : dabs::tcl::commandEntries(parallel)) {
    const std::string pyName(e->name);
    PyObject* fn = makeCommand(st, e);
    PyObject* n = fromView(e->name);
    if (fn == nullptr || n == nullptr || PyList_Append(names, n) != 0 ||
        PyModule_AddObject(module, pyName.c_str(), fn) != 0) {
      Py_XDECREF(fn);
      Py_XDECREF(n);
      Py_DECREF(names);
      return -1;
    }
    Py_DECREF(n);
  }
  // dabs.commands: the names of the DABS commands, in table order.
  if (PyModule_AddObject(module, "commands", names) != 0) {
    Py_DECREF(names);
    return -1;
  }
  // Close the recorders before Python finalises, as the dabs program does at exit.
  PyObject* atexit = PyImport_ImportModule("atexit");
  if (atexit == nullptr) return -1;
  PyObject* down = PyObject_GetAttrString(module, "_shutdown");
  PyObject* r = down != nullptr ? PyObject_CallMethod(atexit, "register", "O", down) : nullptr;
  Py_XDECREF(r);
  Py_XDECREF(down);
  Py_DECREF(atexit);
  return r != nullptr ? 0 : -1;
}

int moduleTraverse(PyObject* module, visitproc visit, void* arg) {
  State* st = stateOf(module);
  if (st != nullptr) {
    Py_VISIT(st->error);
    Py_VISIT(st->commandType);
  }
  return 0;
}

int moduleClear(PyObject* module) {
  State* st = stateOf(module);
  if (st != nullptr) {
    Py_CLEAR(st->error);
    Py_CLEAR(st->commandType);
  }
  return 0;
}

void moduleFree(void* module) {
  State* st = stateOf(static_cast<PyObject*>(module));
  shutdownState(st);
  moduleClear(static_cast<PyObject*>(module));
}

PyModuleDef_Slot kModuleSlots[] = {
    {Py_mod_exec, reinterpret_cast<void*>(moduleExec)},
    {0, nullptr},
};

PyModuleDef kModule = {
    PyModuleDef_HEAD_INIT,
    "dabs",
    "DABS from Python, in OpenSeesPy's style: one function per DABS command (dabs.node, "
    "dabs.element, dabs.analyze, ...), dabs.tcl(script) for Tcl, dabs.OpenSeesError for failed "
    "commands. See the README's Python section.",
    sizeof(State),
    kModuleMethods,
    kModuleSlots,
    moduleTraverse,
    moduleClear,
    moduleFree,
};

}  // namespace

PyMODINIT_FUNC PyInit_dabs() { return PyModuleDef_Init(&kModule); }
