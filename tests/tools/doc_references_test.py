#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Every repository path the README, docs/*.md and the case folders' READMEs name in backticks exists, and every
`hemoscale SUBCOMMAND` they show is one the binary has (issue 31, deliverable 8: docs that match the code).

Usage: doc_references_test.py SOURCE_DIR HEMOSCALE_BINARY
Placeholders (run-NNN, PREFIX, NAME, <...>, globs, $VARS) are not paths and are skipped; a module path such as
`resolved/cases/cell_simulation` is looked up under src/ too, with or without .hpp/.cpp.
"""
import glob
import os
import re
import subprocess
import sys

TOP = ("cases", "docs", "tools", "data", "scripts", "src", "bench", "tests", "app", "validate")
PATH = re.compile(r"`([^`\s]*?(?:%s)/[^`\s]*)`" % "|".join(TOP))
# A command: in a code block, or in backticks, or as a path to the binary (prose says "hemoscale resolves ...").
COMMAND = re.compile(r"(?:`|/)hemoscale\s+([a-z][a-z-]*)")
BLOCK_COMMAND = re.compile(r"\bhemoscale\s+([a-z][a-z-]*)")
PLACEHOLDER = re.compile(r"NNN|PREFIX|NAME|[*<>{}$]")


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


def main():
    root, binary = sys.argv[1], sys.argv[2]
    known = subcommands(binary)
    if not known:
        print("no subcommands in `hemoscale --help`")
        return 1
    problems = []
    checked = 0
    for doc in documents(root):
        name = os.path.relpath(doc, root)
        with open(doc, encoding="utf-8") as f:
            in_block = False
            for number, line in enumerate(f, 1):
                if line.lstrip().startswith("```"):
                    in_block = not in_block
                    continue
                for match in PATH.finditer(line):
                    path = match.group(1)
                    if path.startswith(("/", "../")) or PLACEHOLDER.search(path):
                        continue
                    checked += 1
                    if not exists(root, path):
                        problems.append(f"{name}:{number}: `{path}` does not exist")
                for match in (BLOCK_COMMAND if in_block else COMMAND).finditer(line):
                    checked += 1
                    if match.group(1) not in known:
                        problems.append(f"{name}:{number}: `hemoscale {match.group(1)}` is no subcommand ({', '.join(sorted(known))})")
    for p in problems:
        print(p)
    print(f"{checked} references checked, {len(problems)} broken")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
