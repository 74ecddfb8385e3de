#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# The module rules of DESIGN.md, checked on the #include lines of src/ and on the CMake link graph of the build.
"""Fails (exit 1, one line per violation) when a module reads what it must not:

  - a solver includes or links its partner: fvm/ <-> dem/, lbm/ <-> membrane/ (coupling/ and ibm/ couple them);
  - a solver (resolved/, unresolved/) includes or links analysis/ (analysis reads solver results, never the reverse);
  - unresolved/ (or the closure evaluation, hs_closures) includes or links the GP engine: any regression/ header
    but the expression parser and evaluator, or the closure-fitting workflow (closures/closure_fit, fit_request,
    sha256: hs_closures_fit): a solver evaluates closures only.

Includes are followed transitively through src/, so a header that drags a forbidden one in is caught where it is
included. The link graph is the file cmake/module_graph.cmake writes at configure time (target: direct hs_ deps).
Usage: check_module_rules.py SRC_DIR LINK_GRAPH_FILE
"""
import re
import sys
from pathlib import Path

# The part of regression/ that evaluating a closure needs (library hs_expression); everything else there is GP.
EXPRESSION_HEADERS = {"regression/op.hpp", "regression/expression.hpp", "regression/infix.hpp",
                      "regression/compiled_program.hpp", "regression/data_view.hpp", "regression/dimension.hpp"}
FIT_HEADERS = {"closures/closure_fit.hpp", "closures/fit_request.hpp", "closures/sha256.hpp"}


def is_gp_header(h):
    return (h.startswith("regression/") and h not in EXPRESSION_HEADERS) or h in FIT_HEADERS


# (files whose path under src/ starts with this, forbidden included header predicate, why)
INCLUDE_RULES = [
    ("unresolved/fvm/", lambda h: h.startswith("unresolved/dem/"), "fvm/ never includes dem/ (coupling/ couples them)"),
    ("unresolved/dem/", lambda h: h.startswith("unresolved/fvm/"), "dem/ never includes fvm/ (coupling/ couples them)"),
    ("resolved/lbm/", lambda h: h.startswith("resolved/membrane/"), "lbm/ never includes membrane/ (ibm/ couples them)"),
    ("resolved/membrane/", lambda h: h.startswith("resolved/lbm/"), "membrane/ never includes lbm/ (ibm/ couples them)"),
    ("resolved/", lambda h: h.startswith("analysis/"), "no solver reads analysis/"),
    ("unresolved/", lambda h: h.startswith("analysis/"), "no solver reads analysis/"),
    ("unresolved/", is_gp_header, "unresolved/ evaluates closures and never includes the GP engine"),
    ("closures/", is_gp_header, "evaluating a closure (hs_closures) needs the expression parser only"),
]
# Files a rule's prefix matches but that the rule does not cover: hs_closures_fit, the fitting workflow.
RULE_EXEMPT_FILES = {"closures/": {"closures/closure_fit.cpp", "closures/closure_fit.hpp", "closures/fit_request.cpp",
                                   "closures/fit_request.hpp", "closures/sha256.cpp", "closures/sha256.hpp"}}

SOLVER_LIBS = ["hs_lbm", "hs_membrane", "hs_ibm", "hs_measure", "hs_resolved_cases",
               "hs_fvm", "hs_dem", "hs_coupling", "hs_unresolved_cases"]
UNRESOLVED_LIBS = ["hs_fvm", "hs_dem", "hs_coupling", "hs_unresolved_cases"]
# (library, library it must not reach through its links, why)
LINK_RULES = [("hs_fvm", "hs_dem", "fvm never links dem"), ("hs_dem", "hs_fvm", "dem never links fvm"),
              ("hs_lbm", "hs_membrane", "lbm never links membrane"), ("hs_membrane", "hs_lbm", "membrane never links lbm")]
LINK_RULES += [(lib, "hs_analysis", "no solver links analysis") for lib in SOLVER_LIBS]
LINK_RULES += [(lib, gp, "unresolved never links the GP engine") for lib in UNRESOLVED_LIBS + ["hs_closures", "hs_expression"]
               for gp in ("hs_regression", "hs_closures_fit")]

# Known violations, each with its reason. One that is no longer needed is an error too, so the list only shrinks.
INCLUDE_EXCEPTIONS = {}
LINK_EXCEPTIONS = {}

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.MULTILINE)


def direct_includes(src, rel, cache):
    if rel not in cache:
        path = src / rel
        text = path.read_text(errors="replace") if path.is_file() else ""
        found = []
        for h in INCLUDE.findall(text):   # headers of src/ only: beside the file first, then from src/
            beside = (Path(rel).parent / h).as_posix()
            if (src / beside).is_file() and "/" not in h:
                found.append(beside)
            elif (src / h).is_file():
                found.append(h)
        cache[rel] = found
    return cache[rel]


def include_chains(src, rel, cache):
    """Every src/ header reachable from `rel`, with the shortest include chain to it."""
    chains = {}
    todo = [(rel, [rel])]
    while todo:
        cur, chain = todo.pop(0)
        for h in direct_includes(src, cur, cache):
            if h not in chains:
                chains[h] = chain + [h]
                todo.append((h, chain + [h]))
    return chains


def check_includes(src):
    errors, used, cache = [], set(), {}
    files = sorted(p.relative_to(src).as_posix() for p in src.rglob("*") if p.suffix in (".hpp", ".cpp", ".h"))
    for rel in files:
        chains = None
        for prefix, forbidden, why in INCLUDE_RULES:
            if not rel.startswith(prefix) or rel in RULE_EXEMPT_FILES.get(prefix, ()):
                continue
            chains = chains if chains is not None else include_chains(src, rel, cache)
            for h, chain in sorted(chains.items()):
                if not forbidden(h):
                    continue
                culprit = next((c for c in chain if forbidden(c)), h)
                key = (chain[chain.index(culprit) - 1], culprit)
                if key in INCLUDE_EXCEPTIONS:
                    used.add(key)
                    continue
                errors.append(f"src/{rel}: includes {culprit} (via {' -> '.join(chain[:chain.index(culprit) + 1])}): {why}")
    for key, why in INCLUDE_EXCEPTIONS.items():
        if key not in used:
            errors.append(f"stale exception: src/{key[0]} no longer includes {key[1]}; remove it ({why})")
    return sorted(set(errors))


def read_link_graph(path):
    graph = {}
    for line in Path(path).read_text().splitlines():
        if ":" in line:
            name, deps = line.split(":", 1)
            graph[name.strip()] = deps.split()
    return graph


def link_path(graph, start, goal):
    """The shortest chain of links start -> ... -> goal, or None."""
    todo, seen = [[start]], {start}
    while todo:
        chain = todo.pop(0)
        if chain[-1] == goal:
            return chain
        for d in graph.get(chain[-1], []):
            if d not in seen:
                seen.add(d)
                todo.append(chain + [d])
    return None


def check_links(graph):
    errors, used = [], set()
    for lib, forbidden, why in LINK_RULES:
        if lib not in graph:
            continue   # a module not built in this configuration
        chain = link_path(graph, lib, forbidden)
        if chain is None:
            continue
        if (lib, forbidden) in LINK_EXCEPTIONS:
            used.add((lib, forbidden))
            continue
        errors.append(f"{lib} links {forbidden} ({' -> '.join(chain)}): {why}")
    for key, why in LINK_EXCEPTIONS.items():
        if key[0] in graph and key not in used:
            errors.append(f"stale exception: {key[0]} no longer links {key[1]}; remove it ({why})")
    return errors


def main(argv):
    if len(argv) != 3:
        print(__doc__)
        return 2
    src, graph = Path(argv[1]), read_link_graph(argv[2])
    if not graph:
        print(f"{argv[2]}: no link graph (configure with CMake first)")
        return 2
    errors = check_includes(src) + check_links(graph)
    for e in errors:
        print("module rule broken:", e)
    print(f"{len(errors)} module rule violation(s); {len(INCLUDE_RULES)} include rules, {len(LINK_RULES)} link rules, "
          f"{len(INCLUDE_EXCEPTIONS) + len(LINK_EXCEPTIONS)} known exceptions")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
