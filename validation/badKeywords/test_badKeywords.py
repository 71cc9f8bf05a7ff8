# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Every bad keyword caught, from the list the code
checks, and a bounded fuzz of the grain and coupling dictionaries.

The list.  Both programs take -listKeywords: they read and check a case's
set-up as a run does and print one row per keyword their checks read
(inputChecks::keywordRecord: dictionary and scope, keyword, kind,
required or optional, valid range or choices).  The rows of every model
family's case (testing/rmf_families.py's, and the regolith erosion
box for the prescribed gas, Cartesian contacts, erosion planes and
tabulated profiles) are gathered; the test holds no keyword list of its
own, so a keyword the code checks is a keyword the test tries.  The rows
themselves, ranges and choices included, must be those of the list
committed beside the test (keywords.tsv, one row per family and keyword):
a program that reports a wrong range fails there, and not only where its
message and its list agree with each other.  A keyword added or changed
on purpose: the listing found is written to
build/validation/badKeywords/keywords.tsv, to be compared and copied over
the committed one.

Per row, the bad inputs of its kind:
  scalar   below the lower bound, above the upper (each when finite: the
           bound itself when open, half the bound's size beyond it when
           closed), a word (abc);
  label    one below and one above the range, a number with a fraction;
  bool     a word that is no switch (maybe);
  word     a name that is not one of the choices;
  name     a list where a name is wanted;
  vector   two components, a word;
and, for a required keyword, the keyword removed.  Each must stop the
program that reads it (the solver for constant/, the initialiser for
system/*InitialiseDict) with a FatalIOError whose text names the file,
the keyword, the value (or "missing") and the valid range or choices as
the row gives them.

The fuzz.  Cases of the grain families draw 1 to 3 rows of the grain and
coupling dictionaries and set them to random values: inside the range
(uniform, or log-uniform over decades), on and just beyond its bounds,
huge and tiny magnitudes, nan, inf, words, and any of a selector's
choices.  Each case is initialised and run for 3 steps; it must either run
(exit 0, no nan or inf in its log or in any field or parcel file it wrote)
or stop with a FatalIOError: a signal (floating-point exception,
segmentation fault), a FatalError that is not about input, a nan or a
hang fails.  A hang is a program that writes no output for STALL seconds
(no clock bounds a run: a slow machine only waits longer; the cases
print every step, a few seconds apart at most).  CI runs FUZZ_CASES
cases (seeded), --long 300.
"""

import concurrent.futures
import os
import random
import re
import shutil
import subprocess
import tempfile

import pytest

import rmf_families as families
from rmf import foam
from rmf_testing import report, set_in_list

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = foam.PROJECT_DIR
BUILD = os.path.join(ROOT, "build", "validation", "badKeywords")

EROSION_BOX = os.path.join(ROOT, "tutorials", "psi", "regolithErosionBox")
SOLVER = "rarefiedMultiphaseFoam"
INITIALISER = "rarefiedMultiphaseInitialise"
STALL = 300             # s without output from a program: hung
KEYWORDS = os.path.join(HERE, "keywords.tsv")
FUZZ_CASES = 60         # CI; --long: FUZZ_CASES_LONG
FUZZ_CASES_LONG = 300
# The grain families the fuzz draws from (their grain and coupling rows)
FUZZ_FAMILIES = ["mppic", "hybrid", "ntc", "dem", "oneWay", "twoWayDirect",
                 "twoWayIndirect", "Loth", "adaptive", "axisymmetric",
                 "erosionBox"]


def erosion_box(dst, np_, seed=None):
    """The regolith erosion box: prescribed (tabulated) gas, Cartesian
    contacts, erosion planes, grains from a positions file."""
    case = foam.copy_setup(EROSION_BOX, dst)
    foam.run(case, "blockMesh")
    foam.run(case, INITIALISER)
    return case


FAMILY_BUILDERS = {name: build for name, (build, _) in families.FAMILIES.items()
                   if name != "upstreamIsotropy"}
FAMILY_BUILDERS["erosionBox"] = erosion_box


# -- the rows -----------------------------------------------------------------

class Row:
    """One checked keyword, as a program's -listKeywords prints it."""

    def __init__(self, line, app, family):
        self.line = line.rstrip("\n")
        _, name, self.keyword, self.kind, required, self.valid = \
            self.line.split("\t")
        self.required = required == "required"
        self.file, _, scope = name.partition(".")
        self.scope = scope.split(".") if scope else []
        self.app = app
        self.family = family

    @property
    def key(self):
        return (self.file, tuple(self.scope), self.keyword)

    @property
    def entry(self):
        """foamDictionary's path of the entry."""
        return "/".join(self.scope + [self.keyword])

    def __str__(self):
        return f"{self.file}:{self.entry}"


def list_rows(case, app, family):
    code, out = run_app(case, app, "-listKeywords")
    assert code == 0, (family, app, out[-2000:])
    return [Row(line, app, family) for line in out.splitlines()
            if line.startswith("checkedKeyword\t")]


def _flatten(case):
    """Write the coupling type into grainsProperties (foamDictionary -set,
    which the bad inputs use, drops the #includeIfPresent of the case's
    constant/couplingType and with it the coupling)."""
    path = os.path.join(case, "constant", "couplingType")
    if os.path.exists(path):
        kind = re.search(r"interphaseCoupling\s+(\w+)", open(path).read()).group(1)
        foam.set_entry(case, families.GRAINS, "subModels/interphaseCoupling", kind)


def _one_step(case):
    """One step, written in ascii (the fuzz reads the files for nan)."""
    foam.set_steps(case, 1)
    foam.set_entry(case, families.CONTROL, "writeFormat", "ascii")


@pytest.fixture(scope="module")
def bases():
    """family -> its meshed, initialised case (one solver step to run)."""
    cases = {}
    for name, build in FAMILY_BUILDERS.items():
        # (seeded: every optional coefficient dictionary of the streams
        # is written, so that its keywords are listed)
        case = build(os.path.join(BUILD, "base", name), 1, seed=1)
        _flatten(case)
        _one_step(case)
        cases[name] = case
    return cases


@pytest.fixture(scope="module")
def rows(bases):
    """Every checked keyword of every family (the first family that checks
    it), and the rows of each family."""
    table = {}
    per_family = {}
    for name, case in bases.items():
        found = list_rows(case, SOLVER, name)
        solver_keys = {r.key for r in found}
        found += [r for r in list_rows(case, INITIALISER, name)
                  if r.key not in solver_keys]
        per_family[name] = found
        for r in found:
            table.setdefault(r.key, r)
    return list(table.values()), per_family


HEADER = """\
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
# The keywords the programs check, per family of validation/badKeywords:
# family, program, then the row -listKeywords prints (dictionary and scope,
# keyword, kind, required or optional, valid range or choices), tab
# separated.  test_badKeywords.py::test_rows_as_committed compares the
# programs' listing with it and writes the listing it found to
# build/validation/badKeywords/keywords.tsv.
"""


def _listing(per_family):
    """Every family's rows as lines of keywords.tsv, sorted."""
    return sorted(f"{family}\t{r.app}\t{r.line}"
                  for family, found in per_family.items() for r in found)


def test_rows_as_committed(rows):
    """Every family's rows (keyword, kind, required, range or choices) are
    those of the committed list keywords.tsv, neither more nor fewer."""
    _, per_family = rows
    found = _listing(per_family)
    os.makedirs(BUILD, exist_ok=True)
    with open(os.path.join(BUILD, "keywords.tsv"), "w") as f:
        f.write(HEADER + "".join(line + "\n" for line in found))
    with open(KEYWORDS) as f:
        committed = [line.rstrip("\n") for line in f
                     if line.strip() and not line.startswith("#")]
    missing = sorted(set(committed) - set(found))
    extra = sorted(set(found) - set(committed))
    for line in missing:
        print(f"FAIL keyword list: committed, not listed: {line!r}")
    for line in extra:
        print(f"FAIL keyword list: listed, not committed: {line!r}")
    assert report("keyword list", not missing and not extra,
                  f"{len(found)} rows of {len(per_family)} families; committed "
                  f"rows not listed {len(missing)}, listed rows not committed "
                  f"{len(extra)} (keywords.tsv)")


# -- editing one entry ----------------------------------------------------------

def set_value(case, row, value):
    """Set row's keyword to value (None: remove it)."""
    path = os.path.join(case, row.file)
    if "patches" in row.scope[:-1]:
        set_in_list(path, row.scope[-2], row.scope[-1], row.keyword, value)
    elif value is None:
        foam.remove_entry(case, row.file, row.entry)
    else:
        try:
            foam.set_entry(case, row.file, row.entry, value)
        except subprocess.CalledProcessError:
            # An optional sub-dictionary the case leaves out (controlDict's
            # loadBalance): foamDictionary -set makes no parents
            for i in range(1, len(row.scope) + 1):
                parent = "/".join(row.scope[:i])
                if subprocess.run(["foamDictionary", "-entry", parent, path],
                                  capture_output=True).returncode != 0:
                    foam.set_entry(case, row.file, parent, "{}")
            foam.set_entry(case, row.file, row.entry, value)


class edited:
    """Within the block, the case's dictionaries of the rows hold the new
    values; restored afterwards."""

    def __init__(self, case, changes):
        self.case, self.changes = case, changes

    def __enter__(self):
        self.saved = {}
        for row, _ in self.changes:
            path = os.path.join(self.case, row.file)
            self.saved.setdefault(path, open(path).read())
        for row, value in self.changes:
            set_value(self.case, row, value)
        return self

    def __exit__(self, *exc):
        for path, text in self.saved.items():
            open(path, "w").write(text)


# -- the bad inputs -------------------------------------------------------------

def _number(text):
    """A bound's value: a number, a fraction (5/3), or the number that ends a
    description (alphaPacked = 0.6); None for inf."""
    text = text.strip()
    if text in ("inf", "-inf"):
        return None
    if re.fullmatch(r"[\d.]+/[\d.]+", text):
        a, b = text.split("/")
        return float(a)/float(b)
    return float(re.findall(r"[-+]?[\d.]+(?:e[-+]?\d+)?", text)[-1])


def _interval(valid):
    m = re.search(r"([\[(])\s*([^,]+),\s*(.+?)\s*([\])])\s*$", valid)
    lo, hi = _number(m.group(2)), _number(m.group(3))
    return lo, hi, m.group(1) == "(", m.group(4) == ")"


def _g(x):
    return f"{x:g}"


def bad_values(row):
    """(value, the value's text in the message) of row's kind; value None:
    the keyword removed."""
    values = []
    if row.kind == "scalar":
        lo, hi, open_lo, open_hi = _interval(row.valid)
        if lo is not None:
            values.append(_g(lo) if open_lo else _g(lo - (abs(lo) or 1)/2))
        if hi is not None:
            # (an open bound given as a description, the mesh's diagonal,
            # is printed rounded: a little beyond it)
            plain = re.search(r",\s*[-+\d.e]+\s*[\])]$", row.valid)
            values.append(_g(hi if plain else hi*1.001) if open_hi
                          else _g(hi + (abs(hi) or 1)/2))
        values.append("abc")
    elif row.kind == "label":
        lo, hi = (int(x) for x in re.findall(r"-?\d+", row.valid)[-2:])
        values.append(str(lo - 1))
        if hi < 2**31 - 1:
            values.append(str(hi + 1))
        values.append("1.5")
    elif row.kind == "bool":
        values.append("maybe")
    elif row.kind == "word":
        values.append("noSuchChoice")
    elif row.kind == "name":
        values.append("(a b)")
    elif row.kind == "vector":
        values += ["(1 2)", "abc"]
    else:
        pytest.fail(f"{row}: unknown kind {row.kind}")
    if row.required:
        values.append(None)
    return values


def _squeeze(text):
    return re.sub(r"\s+", "", text)


def run_app(case, app, *args):
    """(exit code, output) of app on case; a hang (no output for STALL
    seconds) is code None."""
    with tempfile.TemporaryFile() as out:
        proc = subprocess.Popen([app, *args], cwd=case, stdout=out,
                                stderr=subprocess.STDOUT)
        seen = -1
        while True:
            try:
                code = proc.wait(timeout=STALL)
                break
            except subprocess.TimeoutExpired:
                size = os.fstat(out.fileno()).st_size
                if size == seen:
                    proc.kill()
                    proc.wait()
                    code = None
                    break
                seen = size
        out.seek(0)
        return code, out.read().decode(errors="replace")


def try_bad(case, row, value):
    """'' when app stops with the FatalIOError the row promises, else what
    was wrong."""
    with edited(case, [(row, value)]):
        code, out = run_app(case, row.app)
    if code == 0:
        return "accepted"
    if code is None or code < 0 or code > 1:
        return f"exit {code}"
    shown = "missing" if value is None else value
    wanted = ["FOAM FATAL IO ERROR", row.file, f"'{row.keyword}'", shown, row.valid]
    flat = _squeeze(out)
    missing = [t for t in wanted if _squeeze(t) not in flat]
    return "message lacks " + ", ".join(repr(t) for t in missing) if missing else ""


def test_every_bad_keyword_caught(bases, rows):
    table, per_family = rows
    kinds = {}
    for r in table:
        kinds[r.kind] = kinds.get(r.kind, 0) + 1
    print(f"checked keywords: {len(table)} rows from {len(bases)} families "
          f"({', '.join(f'{k} {n}' for k, n in sorted(kinds.items()))})")
    # Every family's rows must include its own models' (sanity of the list)
    assert len(table) > 100, len(table)

    # One worker per family's case (edits of one case never overlap)
    by_family = {}
    for r in table:
        by_family.setdefault(r.family, []).append(r)

    def family_run(name):
        results = []
        for r in by_family[name]:
            for value in bad_values(r):
                results.append((r, value, try_bad(bases[name], r, value)))
        return results

    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        results = [x for part in pool.map(family_run, sorted(by_family))
                   for x in part]

    failed = [(r, v, why) for r, v, why in results if why]
    for r, v, why in failed:
        print(f"FAIL bad keyword {r} = {v}: {why}")
    files = sorted({r.file for r in table})
    ok = report("bad keywords", not failed,
                f"{len(results) - len(failed)} of {len(results)} bad inputs caught "
                f"with file, keyword, value and valid range ({len(table)} keywords "
                f"in {len(files)} files: {', '.join(files)})")
    assert ok


# -- known gaps, each with its own case ---------------------------------------

def _case(bases, family, name):
    return foam.copy_case(bases[family], os.path.join(BUILD, name))


def _expect(out, *texts):
    missing = [t for t in ("FOAM FATAL IO ERROR",) + texts if t not in out]
    assert not missing, (missing, out[-2000:])


def test_wedge_too_wide(bases):
    """A wedge of 10 degrees (the axisymmetric case's 2.5 scaled by 4
    across the wedge) is refused: the radial weighting assumes a thin
    wedge."""
    case = _case(bases, "axisymmetric", "wideWedge")
    foam.run(case, "transformPoints", "-scale", "(1 1 4)")
    code, out = run_app(case, SOLVER)
    assert code == 1
    _expect(out, "constant/dsmcProperties", "'axisymmetric'", "at most 5 degrees",
            "wedge angle")


def test_wedge_off_axis(bases):
    """A wedge moved 1 mm off the axis is refused."""
    case = _case(bases, "axisymmetric", "offAxis")
    foam.run(case, "transformPoints", "-translate", "(0 0.001 0)")
    code, out = run_app(case, SOLVER)
    assert code == 1
    _expect(out, "'axisymmetric'", "reaching the axis", "from the x axis")


def test_injection_axisymmetric(bases):
    """Injection models with axisymmetric grains are refused (the radial
    weights of injected parcels are not set)."""
    case = _case(bases, "axisymmetric", "injection")
    foam.set_entry(case, families.GRAINS, "subModels/injectionModels",
                   "{ none { type none; } }")
    code, out = run_app(case, SOLVER)
    assert code == 1
    _expect(out, "'injectionModels'", "none with axisymmetric true")


def test_unknown_gravity_zone(bases):
    """zonalGravity naming a cellZone the mesh does not have."""
    case = _case(bases, "mppic", "gravityZone")
    foam.set_entry(case, families.GRAINS, "subModels/particleForces",
                   "{ zonalGravity { zeroGravityZone nowhere; } }")
    code, out = run_app(case, SOLVER)
    assert code == 1
    _expect(out, families.GRAINS, "'zeroGravityZone'", "nowhere", "one of")


def test_adjust_time_step_without_gas(bases):
    """adjustTimeStep in a case without gas (the Snider column in vacuum):
    there is nothing to set the step from."""
    case = _case(bases, "mppic", "adjustVacuum")
    foam.set_entry(case, "system/controlDict", "adjustTimeStep", "yes")
    code, out = run_app(case, SOLVER)
    assert code == 1
    _expect(out, "system/controlDict", "'adjustTimeStep'", "yes", "constant/dsmcProperties")


# -- the fuzz -------------------------------------------------------------------

FUZZ_FILES = ("constant/grainsProperties", "system/grainsInitialiseDict")
WORDS = ["abc", "nan", "inf", "-inf", "(1 2 3)", "{}", "0x10"]


def fuzz_value(rnd, row):
    """A random value for row: mostly of its kind and often valid."""
    if rnd.random() < 0.1:
        return rnd.choice(WORDS)
    if row.kind == "scalar":
        lo, hi, _, _ = _interval(row.valid)
        lo_ = lo if lo is not None else -1e6
        hi_ = hi if hi is not None else (lo_ + 1)*1e6
        pick = rnd.random()
        if pick < 0.4:
            x = rnd.uniform(lo_, hi_)
        elif pick < 0.6 and lo_ >= 0:
            x = lo_ + 10**rnd.uniform(-8, 6)
        elif pick < 0.8:
            x = rnd.choice([lo_, hi_, lo_ - 1e-9, hi_ + 1e-9, 0.0])
        else:
            x = rnd.choice([1e300, -1e300, 1e-300, -1e-300, 1e30, -1.0])
        return f"{x:.10g}"
    if row.kind == "label":
        lo, hi = (int(x) for x in re.findall(r"-?\d+", row.valid)[-2:])
        return str(rnd.choice([lo, min(hi, lo + 100), rnd.randint(lo, min(hi, lo + 1000)),
                               lo - 1, 2**31, -2**31]))
    if row.kind == "bool":
        return rnd.choice(["true", "false", "yes", "off", "2", "maybe"])
    if row.kind == "word":
        return rnd.choice(row.valid.split()[2:] + ["noSuchChoice"])
    if row.kind == "vector":
        return "({} {} {})".format(*(f"{rnd.uniform(-100, 100):.6g}" for _ in range(3)))
    return rnd.choice(WORDS)


NAN = re.compile(r"(?<![\w.])[-+]?(nan|inf)(?![\w.])", re.IGNORECASE)


def _nan_in_output(case):
    """A file of the last time directory (fields, parcels) or the log with
    a nan or inf: its path."""
    last = foam.latest_time(case)
    if last == "0":
        return None
    for root, _, names in os.walk(os.path.join(case, last)):
        for name in names:
            with open(os.path.join(root, name), errors="replace") as f:
                if NAN.search(f.read()):
                    return os.path.join(root, name)
    return None


def fuzz_case(base, rows, seed, dst):
    """Run one fuzz case: (what was set, outcome, failure or '')."""
    rnd = random.Random(seed)
    pool = [r for r in rows if r.file in FUZZ_FILES]
    picks = rnd.sample(pool, min(len(pool), rnd.randint(1, 3)))
    changes = [(r, fuzz_value(rnd, r)) for r in picks]
    case = foam.copy_case(base, dst)
    for d in os.listdir(case):
        if re.fullmatch(r"[\d.e-]+", d) and d != "0":
            shutil.rmtree(os.path.join(case, d))
    what = "; ".join(f"{r.entry} = {v}" for r, v in changes)
    with edited(case, changes):
        for app in (INITIALISER, SOLVER):
            code, out = run_app(case, app)
            if code is None:
                return what, "hang", f"{app} wrote nothing for {STALL} s"
            if code == 0:
                if NAN.search(out):
                    return what, "nan", f"{app}: nan or inf in its output"
                continue
            if code == 1 and "FOAM FATAL IO ERROR" in out:
                return what, "refused", ""
            tail = "\n    ".join(out.strip().splitlines()[-6:])
            return what, "crash", f"{app} exit {code}:\n    {tail}"
    bad = _nan_in_output(case)
    if bad:
        return what, "nan", f"nan or inf in {bad}"
    shutil.rmtree(case)
    return what, "ran", ""


def _fuzz(bases, rows, n):
    _, per_family = rows
    names = [f for f in FUZZ_FAMILIES if f in bases]
    jobs = []
    for i in range(n):
        family = names[i % len(names)]
        jobs.append((family, 1000 + i))

    def one(job):
        family, seed = job
        dst = os.path.join(BUILD, "fuzz", f"{family}-{seed}")
        return (family, seed) + fuzz_case(bases[family], per_family[family], seed, dst)

    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        results = list(pool.map(one, jobs))

    counts = {}
    for family, seed, what, outcome, why in results:
        counts[outcome] = counts.get(outcome, 0) + 1
        if why:
            print(f"FAIL fuzz {family} seed {seed} ({what}): {why}")
    failed = [r for r in results if r[4]]
    ok = report("fuzz", not failed,
                f"{len(results)} cases over {len(names)} families: "
                + ", ".join(f"{k} {v}" for k, v in sorted(counts.items()))
                + " (ran: exit 0 and no nan/inf; refused: FatalIOError)")
    assert ok


def test_fuzz(bases, rows):
    _fuzz(bases, rows, FUZZ_CASES)


@pytest.mark.long
def test_fuzz_long(bases, rows):
    _fuzz(bases, rows, FUZZ_CASES_LONG)
