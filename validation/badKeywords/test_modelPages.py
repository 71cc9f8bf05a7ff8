# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The model pages (doc/models/*.md) against the keyword listing.

Each page's keyword tables, between <!-- keywords:NAME --> markers, must
be what rmf.keywords makes of keywords.tsv (the programs' -listKeywords,
which test_badKeywords.py checks against the programs themselves), and
every keyword of the listing must be in some page's table: a keyword
added, removed or given another range in the code, once keywords.tsv is
updated, fails here until `/usr/bin/python3 -m rmf.keywords --write`
rewrites the tables.  Every page has the parts of doc/models/README.md.
No program is run: the test reads files only.
"""

import os
import re

from rmf import keywords
from rmf_testing import report

PARTS = ["Syntax", "Examples", "Description", "Restrictions", "Related",
         "Defaults", "Errors"]


def test_tables_as_generated():
    """Every table as rmf.keywords writes it from keywords.tsv, and every
    keyword of the listing in a table."""
    rows = keywords.merged(keywords.read_rows())
    pages = keywords.pages()
    problems = keywords.check(pages, rows)
    ok = report("model pages' keyword tables", not problems,
                f"{len(pages)} pages, {len(rows)} keywords, "
                f"{len(problems)} lines differ or missing")
    assert ok, "".join(problems)


def test_check_sees_a_changed_row(tmp_path):
    """The check itself: a page whose table lost a row, or has a row with
    another range, is reported."""
    rows = keywords.merged(keywords.read_rows())
    page = os.path.join(keywords.PAGES, "grain-collisions.md")
    with open(page, encoding="utf-8") as f:
        text = f.read()
    changed = tmp_path / "changed.md"
    changed.write_text(text.replace("| [0, 1] |", "| [0, 2] |", 1),
                       encoding="utf-8")
    dropped = tmp_path / "dropped.md"
    dropped.write_text(re.sub(r"\n\| `[^\n]*alphaSwitch[^\n]*", "", text),
                       encoding="utf-8")
    assert changed.read_text(encoding="utf-8") != text
    assert dropped.read_text(encoding="utf-8") != text
    assert keywords.check([str(changed)], rows)
    assert keywords.check([str(dropped)], rows)


def test_pages_have_their_parts():
    """Each page has the parts of every model page, in order, and a
    keyword table."""
    missing = []
    for path in keywords.pages():
        if os.path.basename(path) == "README.md":
            continue
        with open(path, encoding="utf-8") as f:
            text = f.read()
        heads = re.findall(r"^## (\w+)", text, re.M)
        if heads != PARTS or "<!-- keywords:" not in text:
            missing.append(f"{os.path.basename(path)}: {heads}")
    ok = report("model pages' parts", not missing,
                f"{len(keywords.pages()) - 1} pages with "
                f"{', '.join(PARTS)}")
    assert ok, "\n".join(missing)
