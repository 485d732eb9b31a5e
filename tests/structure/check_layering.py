#!/usr/bin/python3
# The floors of the engine: every concept (a folder of include/growthuq/ and src/) may include
# its own headers and those of concepts below it in CONCEPT_ORDER, never one above, and an
# installed (public) header may include only public headers, and the command line (src/cli) only
# public headers and its own, as a program built on the installed library would. Scans the
# #include "..." lines and exits non-zero naming every offending include. `--self-test` checks that each rule is
# caught on small made-up trees (and that a clean tree passes).
import argparse
import os
import re
import sys
import tempfile

# Lowest first. core: errors, units, numbers, buffers; evaluation: sample blocks, statuses, the
# evaluator interface and the results of a line; stats: summaries and analyses of those results;
# io: files (INI, CSV, results.h5); then the models' inputs (distributions, correlation,
# sampling), the models (mechanics, fe, correction, fidelity: the choice among them, relaxation,
# forcecurves: stiffness from raw indentation curves, growth), what is built from them (rawdata,
# synthetic), where evaluation runs (pool), the campaign, and the command line on top.
CONCEPT_ORDER = [
    "core", "evaluation", "stats", "io", "distributions", "correlation", "sampling", "sensitivity",
    "mechanics", "fe", "correction", "fidelity", "relaxation", "forcecurves", "growth", "rawdata", "synthetic", "pool",
    "campaign", "cli",
]

# Concepts written on the installed library alone, as a user's program is: besides their own
# headers they include only public ones (the command line is the first user of run_campaign).
PUBLIC_ONLY = {"cli"}

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def source_files(folder):
    for directory, _, names in sorted(os.walk(folder)):
        for name in sorted(names):
            if name.endswith((".hpp", ".cpp", ".h")):
                yield os.path.join(directory, name)


def check(root):
    """The list of problems of the tree at `root` (empty when it keeps every rule)."""
    problems = []
    rank = {concept: i for i, concept in enumerate(CONCEPT_ORDER)}
    public_root = os.path.join(root, "include", "growthuq")
    private_root = os.path.join(root, "src")
    trees = [(public_root, True), (private_root, False)]

    for tree, _ in trees:
        if not os.path.isdir(tree):
            continue
        for entry in sorted(os.listdir(tree)):
            if os.path.isdir(os.path.join(tree, entry)) and entry not in rank:
                problems.append(f"{os.path.relpath(os.path.join(tree, entry), root)}: concept '{entry}' is not in "
                                f"CONCEPT_ORDER of tests/structure/check_layering.py; give it its floor there")
    private_concepts = {e for e in os.listdir(private_root) if os.path.isdir(os.path.join(private_root, e))} \
        if os.path.isdir(private_root) else set()

    for tree, public in trees:
        if not os.path.isdir(tree):
            continue
        for path in source_files(tree):
            relative = os.path.relpath(path, tree)
            if os.sep not in relative:
                continue  # a file beside the concept folders (none today) belongs to no floor
            concept = relative.split(os.sep)[0]
            if concept not in rank:
                continue  # reported above
            with open(path, encoding="utf-8") as source:
                for number, text in enumerate(source, start=1):
                    match = INCLUDE.match(text)
                    if not match:
                        continue
                    target = match.group(1)
                    where = f"{os.path.relpath(path, root)}:{number}"
                    parts = target.split("/")
                    if parts[0] == "growthuq" and len(parts) >= 3:
                        target_concept = parts[1]
                    elif len(parts) >= 2 and parts[0] in private_concepts:
                        target_concept = parts[0]
                        if public:
                            problems.append(f'{where}: #include "{target}": a public header (include/growthuq/) '
                                            f"includes a private one (src/); it would not be installed")
                            continue
                        if concept in PUBLIC_ONLY and target_concept != concept:
                            problems.append(f'{where}: #include "{target}": {concept} is written on the public '
                                            f"library (include/growthuq/) and its own headers only")
                            continue
                    else:
                        if public:
                            problems.append(f'{where}: #include "{target}": a public header may include only '
                                            f'"growthuq/<concept>/..." headers')
                        continue  # a header beside the including file, same concept
                    if target_concept not in rank:
                        problems.append(f'{where}: #include "{target}": unknown concept \'{target_concept}\'')
                    elif rank[target_concept] > rank[concept]:
                        problems.append(f'{where}: #include "{target}": {concept} may not include {target_concept}, '
                                        "which is above it")
    return problems


def write(root, relative, text):
    path = os.path.join(root, relative)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as out:
        out.write(text)


def self_test():
    """Each rule on a made-up tree: the clean tree passes, each violation is named."""
    failures = []
    with tempfile.TemporaryDirectory() as scratch:
        clean = os.path.join(scratch, "clean")
        write(clean, "include/growthuq/core/a.hpp", "#pragma once\n")
        write(clean, "include/growthuq/stats/b.hpp", '#include "growthuq/core/a.hpp"\n')
        write(clean, "src/core/helper.hpp", '#include "growthuq/core/a.hpp"\n')
        write(clean, "src/stats/b.cpp", '#include "growthuq/stats/b.hpp"\n#include "core/helper.hpp"\n'
                                        '#include "local.hpp"\n')
        write(clean, "src/cli/main.cpp", '#include "growthuq/stats/b.hpp"\n#include "options.hpp"\n'
                                         '#include "cli/options.hpp"\n')
        if check(clean):
            failures.append(f"a clean tree was refused: {check(clean)}")

        cases = {
            "upward include": ("src/stats/c.cpp", '#include "growthuq/campaign/d.hpp"\n',
                               'src/stats/c.cpp:1: #include "growthuq/campaign/d.hpp": stats may not include campaign'),
            "upward private include": ("src/core/e.cpp", '\n#include "stats/f.hpp"\n',
                                       'src/core/e.cpp:2: #include "stats/f.hpp": core may not include stats'),
            "public includes private": ("include/growthuq/stats/g.hpp", '#include "core/helper.hpp"\n',
                                        'include/growthuq/stats/g.hpp:1: #include "core/helper.hpp": a public header '
                                        "(include/growthuq/) includes a private one"),
            "command line includes private": ("src/cli/i.cpp", '#include "growthuq/core/a.hpp"\n#include "core/helper.hpp"\n',
                                              'src/cli/i.cpp:2: #include "core/helper.hpp": cli is written on the public '
                                              "library"),
            "concept without a floor": ("src/newthing/h.cpp", "\n",
                                        "src/newthing: concept 'newthing' is not in CONCEPT_ORDER"),
        }
        for index, (name, (relative, text, expected)) in enumerate(cases.items()):
            tree = os.path.join(scratch, f"case{index}")
            write(tree, "include/growthuq/core/a.hpp", "#pragma once\n")
            write(tree, "include/growthuq/campaign/d.hpp", "#pragma once\n")
            write(tree, "src/core/helper.hpp", "#pragma once\n")
            write(tree, "src/stats/f.hpp", "#pragma once\n")
            write(tree, relative, text)
            problems = check(tree)
            if len(problems) != 1 or not problems[0].startswith(expected):
                failures.append(f"{name}: expected one problem starting with {expected!r}, got {problems!r}")
    for failure in failures:
        print(f"self-test: {failure}", file=sys.stderr)
    if not failures:
        print("self-test: a clean tree passes; an upward include, an upward private include, a public header "
              "including a private one, the command line including a private header and a concept without a floor "
              "are each named")
    return 1 if failures else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--source-dir", help="the project's root (holding include/ and src/)")
    parser.add_argument("--self-test", action="store_true")
    arguments = parser.parse_args()
    if arguments.self_test:
        return self_test()
    if not arguments.source_dir:
        parser.error("--source-dir is required")
    problems = check(arguments.source_dir)
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems:
        print(f"{len(problems)} include(s) break the layering " + " < ".join(CONCEPT_ORDER), file=sys.stderr)
        return 1
    print("every include goes to the same floor or one below: " + " < ".join(CONCEPT_ORDER))
    return 0


if __name__ == "__main__":
    sys.exit(main())
