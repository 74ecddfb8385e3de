#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Every repository path the README, docs/*.md and the case folders' READMEs name in backticks exists, every
`hemoscale SUBCOMMAND` they show is one the binary has and every --option they give it is one that subcommand lists
in its --help, and every key they document (a snake_case name in backticks, or `key = value` in a code block) is a
name the code reads: a word of the sources, tests, tools or shipped case files (issue 31, deliverable 8: docs that
match the code; a documented key no parser knows is how `[geometry] shape = "bifurcation"` was documented before any
case read it).

Usage: doc_references_test.py SOURCE_DIR HEMOSCALE_BINARY
Placeholders (run-NNN, PREFIX, NAME, <...>, globs, $VARS) are not paths and are skipped; a module path such as
`resolved/cases/cell_simulation` is looked up under src/ too, with or without .hpp/.cpp.
"""
import glob
import os
import re
import subprocess
import sys

TOP = ("cases", "docs", "tools", "data", "scripts", "src", "bench", "tests", "app", "validate", "study")
PATH = re.compile(r"`([^`\s]*?(?:%s)/[^`\s]*)`" % "|".join(TOP))
# A command: in a code block, or in backticks, or as a path to the binary (prose says "hemoscale resolves ...").
COMMAND = re.compile(r"(?:`|/)hemoscale\s+([a-z][a-z-]*)")
BLOCK_COMMAND = re.compile(r"\bhemoscale\s+([a-z][a-z-]*)")
PLACEHOLDER = re.compile(r"NNN|PREFIX|NAME|[*<>{}$]")
# A documented name: snake_case with at least one underscore (keys, JSON fields, test names), in backticks or as
# the key of a `key = value` line in a code block.
KEY = re.compile(r"[a-z][a-z0-9]*(?:_[a-z0-9]+)+")
INLINE = re.compile(r"`([^`]+)`")
TOML_KEY = re.compile(r"^\s*([a-z][a-z0-9_]*)\s*=")
COMMAND_LINE = re.compile(r"\bhemoscale\s+([a-z][a-z-]*)([^`#|]*)")
OPTION = re.compile(r"(?<![\w-])(--[a-z][a-z-]*)")
CODE_FILES = ("src/**/*.[ch]pp", "app/*.[ch]pp", "bench/*.[ch]pp", "validate/*.[ch]pp", "study/*.[ch]pp", "tools/*.py", "tests/**/*.[ch]pp",
              "tests/**/*.py", "tests/**/CMakeLists.txt", "scripts/*", "cases/**/*.toml", "data/**/*.toml",
              "CMakeLists.txt", "src/**/CMakeLists.txt")


def documents(root):
    files = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    return files + sorted(glob.glob(os.path.join(root, "cases", "**", "README.md"), recursive=True))


def exists(root, path):
    path = path.rstrip(".,:;)").split("::")[0].rstrip("/")
    for base in (root, os.path.join(root, "src")):
        for suffix in ("", ".hpp", ".cpp"):
            if os.path.exists(os.path.join(base, path + suffix)):
                return True
    return False


def subcommands(binary):
    out = subprocess.run([binary, "--help"], capture_output=True, text=True, check=False).stdout
    listed = out.split("Subcommands:", 1)[1] if "Subcommands:" in out else ""
    return {line.split()[0] for line in listed.splitlines() if line.strip()}


def code_words(root):
    """Every identifier in the code, tests, tools and shipped case files, and every file name (a test is named by
    its file)."""
    words = set()
    for pattern in CODE_FILES:
        for path in glob.glob(os.path.join(root, pattern), recursive=True):
            words.add(os.path.splitext(os.path.basename(path))[0])
            with open(path, encoding="utf-8", errors="ignore") as f:
                words.update(re.findall(r"[A-Za-z0-9_]+", f.read()))
    return words


def options_of(binary, sub, cache):
    if sub not in cache:
        out = subprocess.run([binary, sub, "--help"], capture_output=True, text=True, check=False).stdout
        cache[sub] = set(OPTION.findall(out))
    return cache[sub]


def check_line(line, in_block, ctx):
    """The problems of one line of a document; ctx holds the binary, the known names and a counter."""
    problems = []
    for match in PATH.finditer(line):
        path = match.group(1)
        if path.startswith(("/", "../")) or PLACEHOLDER.search(path):
            continue
        ctx["checked"] += 1
        if not exists(ctx["root"], path):
            problems.append(f"`{path}` does not exist")
    for match in (BLOCK_COMMAND if in_block else COMMAND).finditer(line):
        ctx["checked"] += 1
        if match.group(1) not in ctx["known"]:
            problems.append(f"`hemoscale {match.group(1)}` is no subcommand ({', '.join(sorted(ctx['known']))})")
    texts = [line] if in_block else INLINE.findall(line)
    for text in texts:
        for match in COMMAND_LINE.finditer(text):
            sub = match.group(1)
            if sub not in ctx["known"]:
                continue
            for option in OPTION.findall(match.group(2)):
                ctx["checked"] += 1
                if option not in options_of(ctx["binary"], sub, ctx["options"]):
                    problems.append(f"`hemoscale {sub} {option}`: no such option (hemoscale {sub} --help)")
    names = []
    if in_block:
        m = TOML_KEY.match(line)
        if m and "_" in m.group(1):
            names.append(m.group(1))
    else:
        for text in texts:
            names += [k for k in re.split(r"[\s,=()+\[\].:/\"']+", text) if KEY.fullmatch(k)]
    for name in names:
        ctx["checked"] += 1
        if name not in ctx["words"]:
            problems.append(f"`{name}` is documented, but no source, test, tool or case file names it")
    return problems


def main():
    root, binary = sys.argv[1], sys.argv[2]
    known = subcommands(binary)
    if not known:
        print("no subcommands in `hemoscale --help`")
        return 1
    ctx = {"root": root, "binary": binary, "known": known, "words": code_words(root), "options": {}, "checked": 0}
    problems = []
    for doc in documents(root):
        name = os.path.relpath(doc, root)
        with open(doc, encoding="utf-8") as f:
            in_block = False
            for number, line in enumerate(f, 1):
                if line.lstrip().startswith("```"):
                    in_block = not in_block
                    continue
                problems += [f"{name}:{number}: {p}" for p in check_line(line, in_block, ctx)]
    for p in problems:
        print(p)
    print(f"{ctx['checked']} references checked, {len(problems)} broken")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
