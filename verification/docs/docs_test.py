#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The README and docs/ as a reader meets them.

- every markdown link [text](target) in README.md, docs/*.md and examples/README.md that is not a
  web address resolves to a file or folder inside the repository;
- every repository path they name in backticks (verification/..., tcl/..., docs/..., and the
  other source folders) exists, so a renamed script leaves no dangling mention;
- none names a path above the repository (`../something` that resolves outside it: the
  project's tests, docs and main job must stand on a clone alone);
- every command the program registers has a row in the README's command tables (the rows whose
  first cell names commands in backticks), and no command (or `command type` pair, such as
  `element yoshidaBearing`) has two.

usage: docs_test.py <source dir> <dabs program>
"""
import pathlib
import re
import subprocess
import sys
import tempfile

src = pathlib.Path(sys.argv[1]).resolve()
dabs = sys.argv[2]
failures = []


def fail(message):
    failures.append(message)
    print("FAILED", message)


pages = [src / "README.md", src / "examples" / "README.md"] + sorted((src / "docs").glob("*.md"))
roots = ("verification/", "tcl/", "contact/", "elements/", "materials/", "examples/", "docs/", ".ci/")
link = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
code = re.compile(r"`([^`\s]+)`")
checked = 0
for page in pages:
    if not page.exists():
        fail(f"{page.relative_to(src)} is missing")
        continue
    text = page.read_text()
    name = page.relative_to(src)
    for outside in re.findall(r"(?<![\w./])((?:\.\./)+[\w.-]+)", text):
        if not (page.parent / outside).resolve().is_relative_to(src):
            fail(f"{name} names {outside}, outside the repository")
    for target in link.findall(text):
        if re.match(r"[a-z]+://", target) or target.startswith("#") or target.startswith("mailto:"):
            continue
        path = (page.parent / target.split("#")[0]).resolve()
        checked += 1
        if not path.is_relative_to(src):
            fail(f"{name}: link {target} leaves the repository")
        elif not path.exists():
            fail(f"{name}: link {target} does not resolve")
    for token in code.findall(text):
        token = token.rstrip(".,:;")
        if not token.startswith(roots) or any(c in token for c in "*?{}<>$|"):
            continue
        checked += 1
        if not (src / token).exists():
            fail(f"{name}: `{token}` does not exist in the repository")
print(f"{checked} links and repository paths checked in {len(pages)} pages")

# The program's commands: those of its interpreter that a plain interpreter lacks, procs aside.
with tempfile.NamedTemporaryFile("w", suffix=".tcl", delete=False) as script:
    script.write(
        "set plain [interp create]\n"
        "set base [$plain eval {info commands}]\n"
        "interp delete $plain\n"
        "set out {}\n"
        "foreach c [lsort [info commands]] {\n"
        "  if {$c ni $base && $c ni [info procs]} { lappend out $c }\n"
        "}\n"
        "puts $out\n")
run = subprocess.run([dabs, script.name], capture_output=True, text=True, timeout=60)
program = set(run.stdout.split())
if run.returncode != 0 or len(program) < 50:
    fail(f"could not list the program's commands: {run.stdout} {run.stderr}")

# A row documents the commands (or `command type` pairs, such as `element yoshidaBearing`) its
# first cell names in backticks; each may have one row only.
rows = {}
for line in (src / "README.md").read_text().splitlines():
    if not line.startswith("| `"):
        continue
    for key in re.findall(r"`([^`]+)`", line.split("|")[1]):
        key = " ".join(key.split()[:2]) if key.split()[0] in program else key.split()[0]
        rows[key] = rows.get(key, 0) + 1
for key, count in sorted(rows.items()):
    if count != 1:
        fail(f"`{key}`: {count} rows in the README's command tables (one expected)")
documented = {key.split()[0] for key in rows}
for command in sorted(program - documented):
    fail(f"command {command}: no row in the README's command tables")
print(f"{len(program)} commands of the program, {len(rows)} rows' commands and types in the README")
if failures:
    print(f"{len(failures)} failed")
    sys.exit(1)
print("PASSED every link, path and command")
