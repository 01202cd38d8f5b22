#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Seeds and dictionary of the command fuzzer.

Usage: make-seeds.py SOURCE_DIR SEED_DIR [DICT_FILE]

Seeds: every verification script (verification/**/*.tcl) as it is, and one small script per
command row of the README's command tables, its argument pattern turned into numbers after a
small 3D model. Dictionary (when DICT_FILE is given): every command and type word of the command
tables in tcl/commands and every -option word found in their usage strings.
"""
import pathlib
import re
import sys

src = pathlib.Path(sys.argv[1])
seeds = pathlib.Path(sys.argv[2])
seeds.mkdir(parents=True, exist_ok=True)

MODEL = """model basic -ndm 3 -ndf 6
node 1 0.0 0.0 0.0
node 2 1.0 0.0 0.0 -mass 1.0 1.0 1.0 0.1 0.1 0.1
node 3 1.0 1.0 0.0
fix 1 1 1 1 1 1 1
uniaxialMaterial Elastic 1 1000.0
geomTransf Linear 1 0.0 0.0 1.0
timeSeries Linear 1
pattern Plain 1 1 { load 2 1.0 0.0 0.0 0.0 0.0 0.0 }
"""
TAIL = "constraints Plain\nnumberer Plain\nsystem BandGeneral\ntest NormDispIncr 1e-8 10\n" \
       "algorithm Newton\nintegrator Newmark 0.5 0.25\nanalysis Transient\nanalyze 5 0.01\n"

count = 0
for script in sorted(src.glob("verification/**/*.tcl")):
    (seeds / f"script-{count:03d}.tcl").write_bytes(script.read_bytes())
    count += 1


def concrete(pattern):
    """An argument pattern of the README as numbers: optional groups kept, alternatives first."""
    p = pattern.replace("\\|", "|").replace("..", " ")
    p = re.sub(r"\?([^?]*)\?", r"\1", p)
    words = []
    for w in p.split():
        w = w.split("|")[0]
        if w.startswith("-") and not re.match(r"-\d", w):
            words.append(w)
        elif re.match(r"^[A-Za-z]", w) and w[0].isupper():
            words.append(w)  # a type word (Plain, Linear, ...)
        else:
            words.append("1")
    return " ".join(words)


readme = (src / "README.md").read_text()
for row in re.findall(r"^\| *`([^`]+)`[^|]*\| *`([^`]*)`", readme, re.M):
    command, args = row
    for c in command.split("` `"):
        (seeds / f"readme-{count:03d}.tcl").write_text(MODEL + f"{c} {concrete(args)}\n" + TAIL)
        count += 1
print(f"{count} seeds in {seeds}")

if len(sys.argv) > 3:
    words = set()
    for cpp in sorted((src / "tcl" / "commands").glob("*.cpp")):
        text = cpp.read_text()
        words.update(re.findall(r'\{"([A-Za-z][A-Za-z0-9]*)",', text))
        for usage in re.findall(r'"([^"\n]*)"', text):
            words.update(w for w in re.findall(r"(?<![\w-])-[A-Za-z][A-Za-z0-9]*", usage))
    words.update(["{", "}", "[", "]", "$", ";", "\n", "1e308", "-1", "0", "2147483647", "4294967295",
                  "NaN", "1e-300", "-nodeRange", "-eleRange", "analyze", "wipe", "remove", "reset"])
    with open(sys.argv[3], "w") as f:
        f.write("# Command words and options of dabs (made by make-seeds.py)\n")
        for w in sorted(words):
            f.write('"' + w.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\x0A") + '"\n')
    print(f"{len(words)} dictionary words in {sys.argv[3]}")
