#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Grammar of the structure-aware command fuzzer (StructureMutator.cpp).

Usage: make-grammar.py SOURCE_DIR GRAMMAR_FILE

The grammar lists every command and type word the command tables in tcl/commands register, and
for each one some complete command lines ("templates") whose words are the argument slots:
- lines of the verification scripts (variables set to a literal earlier in the same script are
  replaced by that literal; lines with other substitutions are left out);
- one line per command row of the README's command tables, its argument pattern made concrete
  with values that name the small model of the prelude (nodes 1..6, materials, sections, ...);
- one line from the usage string of a table row that neither of the above covers.
A template that creates an object is given the tag 100, so that it does not clash with the
prelude's objects of tags 1..6 and the command reaches its later arguments.

Sections of the file: %prelude (a small 3D model, run before a generated command), %tail (an
analysis that makes the model do some work), %command (one template a line, words separated as in
Tcl). The mutator reads each word's kind (integer, number, option, list, word) from the word itself.
"""
import pathlib
import re
import sys

src = pathlib.Path(sys.argv[1])
out = pathlib.Path(sys.argv[2])

PRELUDE = """model basic -ndm 3 -ndf 6
node 1 0.0 0.0 0.0
node 2 0.0 0.0 3.0
node 3 4.0 0.0 3.0
node 4 4.0 0.0 0.0
node 5 4.0 0.0 3.01
node 6 4.0 1.0 3.0 -mass 1.0 1.0 1.0 0.1 0.1 0.1
fix 1 1 1 1 1 1 1
fix 4 1 1 1 1 1 1
fix 5 0 0 0 1 1 1
uniaxialMaterial Elastic 1 1000.0
uniaxialMaterial Steel02 2 400.0 2.0e5 0.01
uniaxialMaterial Concrete01 3 -30.0 -0.002 -20.0 -0.006
biaxialMaterial Yoshida 1 150.0 0.012 2.0 0.0 0.0 1.0 0.0
section Elastic 1 2.0e8 0.1 1.0e-3 1.0e-3 8.0e7 2.0e-3
section Fiber 2 -GJ 1.0e6 { patch rect 3 4 4 -0.2 -0.2 0.2 0.2; layer straight 2 3 1.0e-4 -0.15 -0.15 0.15 -0.15 }
geomTransf Linear 1 0.0 1.0 0.0
geomTransf PDelta 2 0.0 1.0 0.0
geomTransf Corotational 3 0.0 1.0 0.0
beamIntegration Lobatto 1 1 3
beamIntegration Lobatto 2 2 3
timeSeries Linear 1
timeSeries Path 2 -dt 0.1 -values {0.0 1.0 0.5 -0.2 0.0}
element elasticBeamColumn 1 1 2 0.1 2.0e8 8.0e7 2.0e-3 1.0e-3 1.0e-3 1
element forceBeamColumn 2 2 3 1 1
element zeroLength 3 3 5 -mat 1 1 1 -dir 1 2 3
pattern Plain 1 1 { load 3 1.0 0.0 0.0 0.0 0.0 0.0 }"""

TAIL = """constraints Transformation
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-8 10
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
analyze 3 0.01"""

# Commands that create an object, and the position of its tag (after the command word).
TAG_AT = {"element": 2, "uniaxialMaterial": 2, "biaxialMaterial": 2, "section": 2,
          "geomTransf": 2, "beamIntegration": 2, "timeSeries": 2, "pattern": 2, "node": 1,
          "region": 1, "groundMotion": 1}
# Commands whose second word is a type word.
TYPED = {"element", "uniaxialMaterial", "biaxialMaterial", "section", "geomTransf",
         "beamIntegration", "timeSeries", "pattern", "recorder", "algorithm", "integrator",
         "system", "test", "constraints", "numberer", "analysis", "patch", "layer"}
PER_KEY = 10  # templates kept per command (and type)


def literal_strings(text):
    """Adjacent C++ string literals joined (the usage lines of the tables span several)."""
    return "".join(re.findall(r'"((?:[^"\\]|\\.)*)"', text)).replace('\\"', '"')


# --- the command tables: command names, type words and usage lines ---------------------------
commands = {}  # name -> usage
types = {}  # (command, type) -> usage
table_files = sorted((src / "tcl" / "commands").glob("*.cpp")) + \
    sorted((src / "tcl" / "parallel").glob("*.cpp"))
row = re.compile(r'\{\s*"([A-Za-z][A-Za-z0-9]*)",\s*((?:"(?:[^"\\]|\\.)*"\s*)+|k\w+)\s*,')
for cpp in table_files:
    text = cpp.read_text()
    # Usage lines held in constants (kYoshidaUsage = "...").
    constants = {m.group(1): literal_strings(m.group(2)) for m in re.finditer(
        r'(k\w+)(?:\[\])?\s*=\s*((?:"(?:[^"\\]|\\.)*"\s*)+);', text)}
    for m in re.finditer(r'(\w*Entry)?' + row.pattern, text):
        kind, name, usage = m.group(1) or "", m.group(2), m.group(3)
        usage = literal_strings(usage) if usage.startswith('"') else constants.get(usage, "")
        words = usage.split()
        if kind == "ElementEntry":
            types[("element", name)] = usage
        elif len(words) > 1 and words[1].split("|")[0] == name and words[0] != name:
            types[(words[0], name)] = usage
        elif usage == "" and cpp.name == "SeriesParser.cpp":
            types[("timeSeries", name)] = usage
        elif usage == "" and cpp.name == "RecorderCommands.cpp":
            types[("recorder", name)] = usage
        elif words and words[0] == name:
            commands[name] = usage
        elif m.group(3).startswith("k"):  # a usage line built at run time (kPoundingUsage)
            commands[name] = name
# Type words listed only inside a command's usage (`constraints Plain|Transformation|Penalty`).
for name, usage in commands.items():
    words = usage.split()
    if name in TYPED and len(words) > 1:
        for t in words[1].split("|"):
            if re.fullmatch(r"[A-Za-z][A-Za-z0-9]*", t) and t != "type":
                types.setdefault((name, t), "")


# --- concrete values for the README's and the usage lines' argument names ---------------------
NODE_NAMES = {"i", "j", "iNode", "jNode", "rNode", "cNode", "cNode1", "cNode2", "node", "a", "b",
              "c", "d", "nodeA", "nodeB"}
REF_NAMES = {"matTag", "mat1", "mat2", "m1", "matTag1", "matTag2", "secTag", "secI", "secJ",
             "secE", "transfTag", "integrationTag", "tsTag", "ts", "patternTag", "gmTag", "eleTag",
             "mode", "dof", "dof1", "dir", "perpDirn", "d1", "tag"}
INT_VALUES = {"ndm": "3", "ndf": "6", "N": "3", "nIP": "3", "nY": "2", "nZ": "2", "nIJ": "2",
              "nJK": "2", "nCirc": "4", "nRad": "2", "numBars": "3", "maxIter": "10", "n": "2",
              "numModes": "2", "numIncr": "2", "code": "P", "code1": "P"}
REAL_VALUES = {"Fy": "10.0", "b": "0.02", "gap": "0.01", "tol": "1.0e-6", "dt": "0.01",
               "zeta": "0.05", "E": "1000.0", "A": "0.1", "Iz": "1.0e-3", "Iy": "1.0e-3",
               "G": "8.0e7", "J": "2.0e-3", "gamma": "0.5", "beta": "0.25", "alpha": "0.5"}
TYPE_WORDS = {t for (_, t) in types} | {c.split()[1] for c in ("pattern Plain",)}
NODE_ORDER = ["2", "3", "5", "6", "1", "4"]


def concrete(command, pattern):
    """An argument pattern (README or usage line) as one command line: optional groups kept,
    the first of alternatives, names replaced by values that fit the prelude's model."""
    p = pattern.replace("\\|", "|").replace("..", " ").replace("...", " ")
    p = re.sub(r"\([^)]*\)", " ", p)
    p = re.sub(r"[?<>]", " ", p).replace("{", " { ").replace("}", " } ")
    words, nodes, tag_done = [], 0, False
    for w in p.split():
        w = w.split("|")[0].strip('",;')
        if not w:
            continue
        if w.startswith("-") and re.match(r"-[A-Za-z]", w):
            words.append(w)
        elif w in ("{", "}"):
            words.append(w)
        elif re.fullmatch(r"-?\d+(\.\d*)?(e-?\d+)?", w):
            words.append(w)
        elif w in TYPE_WORDS or w in ("P", "Mz", "Vy", "My", "Vz", "T"):
            words.append(w)  # a type word (Plain, Linear, ...) or a section code
        elif w == "tag" and not tag_done:
            words.append("100")
            tag_done = True
        elif w in NODE_NAMES and not (len(w) == 1 and command.startswith("uniaxialMaterial")):
            words.append(NODE_ORDER[nodes % len(NODE_ORDER)])
            nodes += 1
        elif w in REF_NAMES or re.fullmatch(r"(c|m|d|mat|matTag|dof)\d", w):
            words.append("1")
        elif w in INT_VALUES:
            words.append(INT_VALUES[w])
        elif w in REAL_VALUES:
            words.append(REAL_VALUES[w])
        elif re.fullmatch(r"[a-z]+", w) and w in ("disp", "vel", "accel", "force", "beam", "bar",
                                                  "rect", "quad", "circ", "straight", "basic",
                                                  "element", "node", "run", "kumar", "drop"):
            words.append(w)
        else:
            words.append("1.0")
    line = " ".join([command] + words)
    return re.sub(r"\{ *\}", "{}", line)


# --- verification scripts ------------------------------------------------------------------
def complete_commands(text):
    """The script's top-level commands as single lines (newlines in a braced body become ';')."""
    out, current, depth = [], [], 0
    for raw in text.splitlines():
        line = raw.strip()
        if not current and (not line or line.startswith("#")):
            continue
        if current and (not line or line.startswith("#")):
            continue
        continued = raw.rstrip().endswith("\\")
        current.append((line.rstrip("\\").strip(), continued))
        depth += line.count("{") - line.count("\\{") - line.count("}") + line.count("\\}")
        if depth <= 0 and not continued:
            joined, after_backslash = current[0][0], current[0][1]
            for part, cont in current[1:]:
                brace = joined.endswith("{") or part.startswith("}")
                joined += (" " if brace or after_backslash else "; ") + part
                after_backslash = cont
            out.append(joined)
            current, depth = [], 0
    return out


def with_tag(words):
    """The command's creating tag set to 100 (when it has one)."""
    at = TAG_AT.get(words[0])
    if at is not None and len(words) > at and re.fullmatch(r"-?\d+", words[at]):
        words = list(words)
        words[at] = "100"
    return words


templates = {}  # key -> list of lines


def key_of(words):
    if words[0] in TYPED and len(words) > 1 and (words[0], words[1]) in types:
        return words[0] + " " + words[1]
    return words[0]


def balanced(line):
    """True when the line's braces pair up (a template must be one complete command)."""
    depth = 0
    for ch in line:
        depth += {"{": 1, "}": -1}.get(ch, 0)
        if depth < 0:
            return False
    return depth == 0


def add(line, front=False):
    words = line.split()
    if not words or words[0] not in commands or not balanced(line):
        return
    line = " ".join(with_tag(words)) if "{" not in line else line
    if line.split()[0] in TAG_AT and "{" in line:
        w = line.split(" ")
        w = with_tag(w)
        line = " ".join(w)
    bucket = templates.setdefault(key_of(words), [])
    if line in bucket:
        return
    if front:
        bucket.insert(0, line)
    else:
        bucket.append(line)


def shape(line):
    """What distinguishes templates of one command: the kinds of its words and its options."""
    kinds = []
    for w in line.split():
        if re.fullmatch(r"-?\d+", w):
            kinds.append("i")
        elif re.fullmatch(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?", w):
            kinds.append("r")
        else:
            kinds.append(w)
    return " ".join(kinds)


for script in sorted(src.glob("verification/**/*.tcl")):
    values = {}
    parts = []
    for cmd in complete_commands(script.read_text()):
        # Several commands on a line: each its own template (a braced body keeps its ';').
        parts.extend(c.strip() for c in (cmd.split(";") if "{" not in cmd else [cmd]))
    for cmd in parts:
        m = re.fullmatch(r"set\s+(\w+)\s+([^\s$\[\]{}\"]+)", cmd)
        if m:
            values[m.group(1)] = m.group(2)
            continue
        cmd = re.sub(r"\$(\w+)", lambda v: values.get(v.group(1), "$" + v.group(1)), cmd)
        cmd = re.sub(r"\$\{(\w+)\}", lambda v: values.get(v.group(1), "${" + v.group(1) + "}"),
                     cmd)
        if "$" in cmd or "[" in cmd or len(cmd) > 400:
            continue
        add(cmd)

readme = (src / "README.md").read_text()
for command, args in re.findall(r"^\| *`([^`]+)`[^|]*\| *`([^`]*)`", readme, re.M):
    for c in command.split("` `"):
        words = c.split()
        if not words or words[0] not in commands:
            continue
        for alternative in re.split(r"`, `|` or `", args):
            add(concrete(c, alternative), front=True)

# Rows with no template yet: their usage line.
for (command, t), usage in types.items():
    if command + " " + t not in templates and command in commands:
        pattern = " ".join(usage.split()[2:]) if usage else "tag"
        add(concrete(command + " " + t, pattern), front=True)
for name, usage in commands.items():
    if not any(k == name or k.startswith(name + " ") for k in templates):
        add(concrete(name, " ".join(usage.split()[1:])), front=True)

# Keep a few templates of each command, of different shapes first.
kept = []
for k in sorted(templates):
    lines, shapes, chosen = templates[k], set(), []
    for line in lines:
        if shape(line) not in shapes and len(chosen) < PER_KEY:
            shapes.add(shape(line))
            chosen.append(line)
    kept.extend(chosen)

missing = sorted(n for n in commands if not any(t.split()[0] == n for t in kept))
with open(out, "w") as f:
    f.write("# Grammar of the structure-aware command fuzzer: made by make-grammar.py from the\n"
            "# command tables in tcl/commands, the README's command tables and the verification\n"
            "# scripts. Do not edit; run `python3 tcl/commands/fuzz/make-grammar.py . "
            "tcl/commands/fuzz/commands.grammar`.\n")
    f.write("%prelude\n" + PRELUDE + "\n%tail\n" + TAIL + "\n%command\n")
    for line in kept:
        f.write(line + "\n")
print(f"{len(commands)} commands, {len(types)} types, {len(kept)} templates in {out}"
      + (f"; no template for {', '.join(missing)}" if missing else ""))
