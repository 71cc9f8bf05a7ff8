# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The keyword tables of the model pages (doc/models/*.md), generated from
the programs' keyword listing.

    /usr/bin/python3 -m rmf.keywords [--write] [PAGE.md ...]

validation/badKeywords/keywords.tsv is the committed output of
`rarefiedMultiphaseFoam -listKeywords` and `rarefiedMultiphaseInitialise
-listKeywords` over every model family's case (its test checks that the
programs' listing equals it).  A model page holds one or more tables
between the markers

    <!-- keywords:NAME -->
    ...
    <!-- /keywords:NAME -->

where NAME is one of TABLES below: which dictionaries and keywords the
table shows.  The rows are the listing's, made general: the names a case
chose (species, patches, regions, vibrational modes) become <species>,
<patch>, <region>, <mode>, and a range that quotes the case's mesh is
stated without the number; rows that differ only in such a name are one
row, and a keyword whose range or requirement differs between cases
shows each.

Without --write the pages are checked: every table must be what this
module makes of keywords.tsv, and every keyword of the listing must be in
some table; the differences are printed and the exit status is 1.  With
--write the tables are rewritten in place.  Without PAGE arguments every
page of doc/models is taken.  validation/badKeywords/test_modelPages.py
runs the check.
"""

import argparse
import difflib
import glob
import os
import re
import sys

from rmf import foam

TSV = os.path.join(foam.PROJECT_DIR, "validation", "badKeywords",
                   "keywords.tsv")
PAGES = os.path.join(foam.PROJECT_DIR, "doc", "models")

# Name -> the rows it shows: (scope regex, keyword regex) pairs, matched in
# full against the general scope (file.dictionary.subdictionary...) and
# keyword.  The order of the rows in a table is the order of the pairs,
# then the listing's.
TABLES = {
    "gas-collisions": [
        (r"constant/dsmcProperties", r"BinaryCollisionModel"),
        (r"constant/dsmcProperties\.(\w*VariableHardSphere|\w*VariableSoftSphere)"
         r"Coeffs(\..*)?", r".*"),
        (r"constant/dsmcProperties\.collisionSubSteps", r".*"),
        (r"constant/dsmcProperties\.esBGK", r".*"),
    ],
    "gas-species": [
        (r"constant/dsmcProperties\.moleculeProperties\.<species>", r".*"),
        (r"constant/dsmcProperties\.moleculeProperties\.<species>"
         r"\.vibrationalModes\.<mode>", r".*"),
    ],
    "gas-inflow": [
        (r"constant/dsmcProperties", r"InflowBoundaryModel"),
        (r"constant/dsmcProperties", r"randomEntryTime"),
        (r"constant/dsmcProperties\.(FreeStream|PatchInflow)Coeffs(\..*)?",
         r".*"),
    ],
    "gas-walls": [
        (r"constant/dsmcProperties", r"WallInteractionModel"),
    ],
    "gas": [
        (r"constant/dsmcProperties",
         r"nEquivalentParticles|randomSeed|tracking"),
        (r"system/dsmcInitialiseDict(\..*)?", r".*"),
        (r"system/controlDict", r"maxTransit|maxDeltaT"),
    ],
    "axisymmetric": [
        (r"constant/(dsmcProperties|grainsProperties)",
         r"axisymmetric|radialExtent|maxRadialWeight"),
    ],
    "grain-clouds": [
        (r"constant/grainsProperties",
         r"cloudType|randomSeed|reportInterval|tracking"),
        (r"constant/grainsProperties\.constantProperties", r".*"),
        (r"constant/grainsProperties\.solution", r".*"),
    ],
    "grain-walls": [
        (r"constant/grainsProperties\.subModels", r"patchInteractionModel"),
        (r"constant/grainsProperties\.subModels\."
         r"(localInteraction|standardWallInteraction)Coeffs(\..*)?", r".*"),
    ],
    "grain-fill": [
        (r"system/grainsInitialiseDict(\..*)?", r".*"),
    ],
    "mppic": [
        (r"constant/grainsProperties\.subModels",
         r"packingModel|dampingModel|isotropyModel"),
        (r"constant/grainsProperties\.subModels\."
         r"(twoSided|relaxation|restartableStochastic)Coeffs(\..*)?", r".*"),
    ],
    "grain-collisions": [
        (r"constant/grainsProperties\.subModels", r"stochasticCollisionModel"),
        (r"constant/grainsProperties\.subModels\.NTCHardSphereCoeffs", r".*"),
    ],
    "interphase-coupling": [
        (r"constant/grainsProperties\.subModels",
         r"interphaseCoupling|averagingSteps|lift"),
        (r"constant/grainsProperties\.subModels\."
         r"(Loth|twoWayDirect|twoWayIndirect|adaptive|oneWay)Coeffs(\..*)?",
         r".*"),
    ],
    "dem-contacts": [
        (r"constant/grainsProperties\.subModels", r"collisionModel"),
        (r"constant/grainsProperties\.subModels\."
         r"(pairCollision|cartesianContacts)Coeffs(\..*)?", r".*"),
    ],
    "erosion-planes": [
        (r"constant/grainsProperties\.cloudFunctions\.erosionPlanes", r".*"),
    ],
    "load-balance": [
        (r"system/controlDict\.loadBalance", r".*"),
    ],
}

# The dictionary a case names freely -> its placeholder, for the entry
# that follows it in a scope
NAMED = {"moleculeProperties": "<species>", "vibrationalModes": "<mode>",
         "PatchInflowCoeffs": "<patch>", "patches": "<patch>",
         "regions": "<region>"}
# Scopes whose keywords are species names
SPECIES_KEYS = ("composition", "numberDensities", "alpha")
MESH_RANGE = re.compile(r"the mesh's diagonal = [^)]*")
# A bound set by another keyword of the case: stated by its name
KEYWORD_RANGE = re.compile(r"\b(switchAbove) = [^)]*")

BEGIN = re.compile(r"<!-- keywords:([\w-]+) -->\n")
HEADER = ("| dictionary | keyword | kind | required | valid range or choices |\n"
          "| --- | --- | --- | --- | --- |\n")


def read_rows(path=TSV):
    """The listing's rows as (scope, keyword, kind, required, valid)."""
    rows = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            fields = line.split("\t")
            if len(fields) != 8:
                raise ValueError(f"{path}: not 8 fields: {line!r}")
            rows.append(tuple(fields[3:]))
    return rows


def general(row):
    """The row with the case's own names replaced by placeholders."""
    scope, keyword, kind, required, valid = row
    parts = scope.split(".")
    for i in range(1, len(parts)):
        if parts[i - 1] in NAMED:
            parts[i] = NAMED[parts[i - 1]]
    if parts[-1] in SPECIES_KEYS:
        keyword = "<species>"
    valid = MESH_RANGE.sub("the mesh's diagonal", valid)
    valid = KEYWORD_RANGE.sub(r"\1", valid)
    return (".".join(parts), keyword, kind, required, valid)


def merged(rows):
    """General rows, one per (scope, keyword); where cases differ in the
    requirement or the range, each is shown (a choice list: the union)."""
    order, seen = [], {}
    for row in map(general, rows):
        key = row[:2]
        if key not in seen:
            seen[key] = []
            order.append(key)
        if row[2:] not in seen[key]:
            seen[key].append(row[2:])
    out = []
    for key in order:
        variants = seen[key]
        kinds = _join([v[0] for v in variants])
        required = _join([v[1] for v in variants])
        valids = [v[2] for v in variants]
        if all(v.startswith("one of ") for v in valids):
            words = []
            for v in sorted(valids, key=len, reverse=True):
                words += [w for w in v[7:].split() if w not in words]
            valid = "one of " + " ".join(words)
        else:
            valid = _join(valids)
        out.append(key + (kinds, required, valid))
    return out


def _join(values):
    unique = []
    for v in values:
        if v not in unique:
            unique.append(v)
    return " / ".join(unique)


def select(name, rows):
    """The merged rows the table NAME shows, in its order."""
    chosen = []
    for scope_re, key_re in TABLES[name]:
        for row in rows:
            if (re.fullmatch(scope_re, row[0]) and re.fullmatch(key_re, row[1])
                    and row not in chosen):
                chosen.append(row)
    return chosen


def _cell(text):
    return text.replace("|", "\\|")


def table(name, rows):
    """The Markdown table NAME, from merged rows."""
    lines = [HEADER]
    for scope, keyword, kind, required, valid in select(name, rows):
        lines.append(f"| `{_cell(scope)}` | `{_cell(keyword)}` | {kind} | "
                     f"{required} | {_cell(valid)} |\n")
    return "".join(lines)


def render(text, rows):
    """TEXT with every table between markers made anew from merged rows;
    also the names of the tables found."""
    out, names, pos = [], [], 0
    while True:
        m = BEGIN.search(text, pos)
        if not m:
            out.append(text[pos:])
            break
        name = m.group(1)
        if name not in TABLES:
            raise ValueError(f"unknown keyword table {name!r}")
        end = f"<!-- /keywords:{name} -->"
        j = text.find(end, m.end())
        if j < 0:
            raise ValueError(f"no closing marker for keywords:{name}")
        out += [text[pos:m.end()], table(name, rows)]
        names.append(name)
        pos = j
    return "".join(out), names


def pages():
    return sorted(glob.glob(os.path.join(PAGES, "*.md")))


def check(paths, rows):
    """Differences between the pages and what the listing makes of them,
    and the listing's keywords that no table shows, as lines of text."""
    problems, shown = [], set()
    for path in paths:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        new, names = render(text, rows)
        for name in names:
            shown.update(r[:2] for r in select(name, rows))
        if new != text:
            rel = os.path.relpath(path, foam.PROJECT_DIR)
            problems += difflib.unified_diff(
                text.splitlines(True), new.splitlines(True),
                rel, rel + " (from keywords.tsv)", n=0)
    for row in rows:
        if row[:2] not in shown:
            problems.append(f"in no table: {row[0]} {row[1]}\n")
    return problems


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pages", nargs="*", help="default: doc/models/*.md")
    parser.add_argument("--write", action="store_true",
                        help="rewrite the tables in place")
    parser.add_argument("--tsv", default=TSV, help="the keyword listing")
    args = parser.parse_args(argv)
    rows = merged(read_rows(args.tsv))
    paths = args.pages or pages()
    if args.write:
        for path in paths:
            with open(path, encoding="utf-8") as f:
                text = f.read()
            new, _ = render(text, rows)
            if new != text:
                with open(path, "w", encoding="utf-8") as f:
                    f.write(new)
                print(f"rewrote {os.path.relpath(path, foam.PROJECT_DIR)}")
        return 0
    problems = check(paths, rows)
    sys.stdout.writelines(problems)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
