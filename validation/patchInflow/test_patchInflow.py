# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""PatchInflow: inflow through one patch with a radial
profile of n, T and U, for a gas with rotational energy (water vapour,
doc/physics.md#apollo-psi, mixed here with argon to exercise the composition).

Case: an empty box x in [0, 10] mm, y, z in [-10, 10] mm, 2 x 10 x 10
cells; the x = 0 face (100 faces, centres at r = 1.4 to 12.7 mm from the
x axis) is the inflow patch, every other face an open patch.  Profile
rows at r = 0, 7 and 14 mm, linear in r (so interpolation is exact):
n = 1e23 (1 - r/28 mm) m^-3 (dense, to have
~200 simulators per face in one short step; nothing collides), T = 300 - 100 r/14 mm K, U = (2000 - 500
r/14 mm, 100, 0) m/s; composition H2O 0.75, Ar 0.25.  No collisions
(BinaryCollisionModel none), so the simulators keep what the inflow gave them.

One step of dt = 1e-13 s: every simulator is still within 1 nm of where
it was inserted (it moved c dt), far from the 2 mm face edges, so its
face is known from its (y, z).  Checks:
- count per face and species: the inflow inserts floor or ceil of
  x_s n A dt Gamma(q)/W (Bird 1994 eq. 4.22, computed here), so every
  count is within 1 of it (exact bound: the carried fraction starts at
  0).  Expected per face 63-139 simulators of H2O, 21-46 of Ar.
- velocities, pooled over the faces after subtracting each face's
  expectation: flux-weighted mean normal speed (computed here by
  quadrature of u^2 exp(-(u - q)^2) over u^1 exp(...)), tangential mean
  U_t and variance kT/m; tolerance 5 standard errors of the pooled
  sample (about 9500 H2O and 3200 Ar simulators).
- internal energy: H2O (3 rotational degrees of freedom) has mean
  (3/2) k T of its face, Ar none; tolerance 5 standard errors (the
  equilibrium distribution of 3 degrees has variance (3/2) (kT)^2).
- the step log's "Simulators inserted through nozzle = step / total"
  equals the number of simulators in the domain.
- bad input: unsorted rows, a face outside the rows' r range, a row of
  5 entries, T < 0 in a row, fractions not summing to 1, an unknown
  patch: FatalIOError naming the file, keyword and value.

The counts, the account and Ar's zero internal energy are exact.  The
statistical comparisons are the 11 of test_velocities_and_internal_energy
(per species the normal mean, two tangential means and two variances,
and H2O's internal energy), each at 5 standard errors (5.7e-7 two-sided).
Family-wise error: 11 x 5.7e-7 = 6.3e-6, within 2.5e-4
(rmf_testing.MODULE_ALPHA), Bonferroni.  Seed: randomSeed
rmf_testing.seed(3).
"""

import math
import os

import numpy as np
import pytest
from scipy import integrate, special

from rmf import foam
from rmf_testing import run_failing, seed

TUTORIAL = os.path.join(foam.PROJECT_DIR, "tutorials", "gas", "impingingStream")
BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "patchInflow")
PROPS = "constant/dsmcProperties"
K = 1.380649e-23
M = {"H2O": 2.99e-26, "Ar": 66.3e-27}
ZETA = {"H2O": 3, "Ar": 0}
X = {"H2O": 0.75, "Ar": 0.25}
W = 4e5
DT = 1e-13
H = 2e-3                      # face size
R_ROWS = (0.0, 7e-3, 14e-3)


def profile(r):
    n = 1e23*(1 - r/28e-3)
    T = 300 - 100*r/14e-3
    U = np.stack([2000 - 500*r/14e-3, np.full_like(r, 100.0), np.zeros_like(r)], -1)
    return n, T, U


def rows_text(rows):
    return "(" + " ".join("(" + " ".join(f"{v:.12g}" for v in row) + ")" for row in rows) + ")"


def profile_rows(radii=R_ROWS):
    r = np.array(radii)
    n, T, U = profile(r)
    return [(r[i], n[i], T[i], *U[i]) for i in range(len(r))]


BLOCKMESH = """FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
scale 0.001;
vertices ((0 -10 -10) (10 -10 -10) (10 10 -10) (0 10 -10)
          (0 -10 10) (10 -10 10) (10 10 10) (0 10 10));
blocks (hex (0 1 2 3 4 5 6 7) (2 10 10) simpleGrading (1 1 1));
boundary
(
    nozzle { type patch; faces ((0 4 7 3)); }
    open { type patch; faces ((1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }
);
"""

PROPERTIES = """FoamFile { version 2.0; format ascii; class dictionary; object dsmcProperties; }
nEquivalentParticles %g;
randomSeed %d;
WallInteractionModel MaxwellianThermal;
BinaryCollisionModel none;
InflowBoundaryModel PatchInflow;
PatchInflowCoeffs
{
    nozzle
    {
        composition { H2O 0.75; Ar 0.25; }
        coordinate r;
        axis (1 0 0);
        table %s;
    }
}
typeIdList (H2O Ar);
moleculeProperties
{
    H2O { mass 2.99e-26; diameter 4.5e-10; internalDegreesOfFreedom 3; omega 0.75; }
    Ar { mass 66.3e-27; diameter 4.17e-10; internalDegreesOfFreedom 0; omega 0.81; }
}
"""


def write_properties(case, rows):
    with open(os.path.join(case, PROPS), "w") as f:
        f.write(PROPERTIES % (W, seed(3), rows_text(rows)))


@pytest.fixture(scope="module")
def meshed():
    """The empty box, meshed and initialised (no simulator)."""
    case = foam.copy_setup(TUTORIAL, os.path.join(BUILD, "meshed"))
    with open(os.path.join(case, "system", "blockMeshDict"), "w") as f:
        f.write(BLOCKMESH)
    write_properties(case, profile_rows())
    # One boundary entry for every patch of every initial field
    for field in os.listdir(os.path.join(case, "0")):
        path = os.path.join(case, "0", field)
        with open(path) as f:
            text = f.read()
        head = text[:text.index("boundaryField")]
        if field in ("boundaryT", "boundaryU"):
            value = "uniform 300" if field == "boundaryT" else "uniform (0 0 0)"
            entry = f"type fixedValue; value {value};"
        else:
            entry = "type zeroGradient;"
        with open(path, "w") as f:
            f.write(head + 'boundaryField\n{\n    ".*" { ' + entry + " }\n}\n")
    foam.set_entry(case, "system/dsmcInitialiseDict", "numberDensities", "{ H2O 0; }")
    foam.set_entry(case, "system/controlDict", "deltaT", DT)
    foam.set_entry(case, "system/controlDict", "functions", "{}")
    foam.set_steps(case, 1)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case


def flux(n, T, q_n, m):
    """Bird (1994) eq. 4.22: one-sided number flux [1/m^2/s]."""
    cmp = np.sqrt(2*K*T/m)
    q = q_n/cmp
    return n*cmp*(np.exp(-q*q) + math.sqrt(math.pi)*q*(1 + special.erf(q)))/(2*math.sqrt(math.pi))


def mean_normal(q):
    """Flux-weighted mean of u over c_mp: int u^2 e^-(u-q)^2 / int u e^-(u-q)^2."""
    num = integrate.quad(lambda u: u*u*math.exp(-(u - q)**2), 0, q + 12)[0]
    den = integrate.quad(lambda u: u*math.exp(-(u - q)**2), 0, q + 12)[0]
    return num/den


@pytest.fixture(scope="module")
def inflow(meshed):
    case = foam.copy_case(meshed, os.path.join(BUILD, "profile"))
    log = foam.run(case, "rarefiedMultiphaseFoam")
    t = foam.latest_time(case)
    base = os.path.join(case, t, "lagrangian", "dsmc")
    pos = foam.read_positions(os.path.join(base, "positions"))
    U = foam.read_list(os.path.join(base, "U"))
    Ei = foam.read_list(os.path.join(base, "Ei"))
    typeId = foam.read_list(os.path.join(base, "typeId")).astype(int)
    # Face of each simulator from (y, z)
    iy = np.floor((pos[:, 1] + 10e-3)/H).astype(int)
    iz = np.floor((pos[:, 2] + 10e-3)/H).astype(int)
    return dict(log=log, pos=pos, U=U, Ei=Ei, typeId=typeId, face=iy*10 + iz)


def face_states():
    c = (np.arange(10) + 0.5)*H - 10e-3
    yc, zc = np.meshgrid(c, c, indexing="ij")
    r = np.hypot(yc, zc).ravel()
    n, T, U = profile(r)
    return n, T, U


def test_counts_per_face(inflow):
    n, T, U = face_states()
    assert np.all(inflow["pos"][:, 0] < 1e-8)       # still at the patch
    for s, species in enumerate(("H2O", "Ar")):
        expected = X[species]*n*H*H*DT*flux(1, T, U[:, 0], M[species])/W
        counts = np.bincount(inflow["face"][inflow["typeId"] == s], minlength=100)
        dev = np.abs(counts - expected)
        assert dev.max() < 1, (species, dev.max(), expected.min(), expected.max())
    inserted = foam.log_values(inflow["log"], "Simulators inserted through nozzle")
    assert inserted[-1][0] == len(inflow["typeId"])


def test_velocities_and_internal_energy(inflow):
    n, T, U = face_states()
    for s, species in enumerate(("H2O", "Ar")):
        sel = inflow["typeId"] == s
        f = inflow["face"][sel]
        c = inflow["U"][sel]
        m = M[species]
        cmp = np.sqrt(2*K*T/m)
        sigma = np.sqrt(K*T/m)
        N = sel.sum()
        # Normal: (c_x - <c_x>_f)/sigma_f pooled; <c_x> from the quadrature
        mean_x = np.array([mean_normal(q) for q in U[:, 0]/cmp])*cmp
        zx = (c[:, 0] - mean_x[f])/sigma[f]
        assert abs(zx.mean()) < 5*zx.std()/math.sqrt(N), (species, zx.mean())
        # Tangential: mean U_t, variance kT/m
        for j in (1, 2):
            z = (c[:, j] - U[f, j])/sigma[f]
            assert abs(z.mean()) < 5/math.sqrt(N), (species, j, z.mean())
            # variance of z is 1; its standard error sqrt(2/N)
            assert abs(z.var() - 1) < 5*math.sqrt(2/N), (species, j, z.var())
        # Internal energy: (zeta/2) k T
        e = inflow["Ei"][sel]/(K*T[f])
        if ZETA[species] == 0:
            assert np.all(e == 0)
        else:
            mean = ZETA[species]/2
            assert abs(e.mean() - mean) < 5*math.sqrt(mean/N), (species, e.mean())


def bad_case(meshed, name, rows=None, edit=None):
    case = foam.copy_case(meshed, os.path.join(BUILD, name))
    write_properties(case, rows or profile_rows())
    if edit:
        foam.set_entry(case, PROPS, *edit)
    return run_failing(case, "rarefiedMultiphaseFoam")


@pytest.mark.parametrize("name, rows, edit, texts", [
    ("unsorted", [profile_rows()[i] for i in (0, 2, 1)], None,
     ("table", "row 2: position 0.007 after 0.014", "strictly increasing")),
    ("short", profile_rows((0, 7e-3, 10e-3)), None,
     ("table", "face centre of patch nozzle", "[0, 0.01]")),
    ("fiveColumns", [row[:5] for row in profile_rows()], None,
     ("table", "row 0: 5 columns", "6 (s n T Ux Uy Uz)")),
    ("hot", [row[:2] + (-1,) + row[3:] for row in profile_rows()], None,
     ("table", "row 0: T = -1", "T in (0, inf)")),
    ("fractions", None, ("PatchInflowCoeffs/nozzle/composition/Ar", 0.5),
     ("composition", "1.25", "summing to 1")),
    ("unknownPatch", None, ("PatchInflowCoeffs/nozzel", "{ composition { H2O 1; } n 1; T 1; U (0 0 0); }"),
     ("nozzel", "open", "nozzle")),
])
def test_bad_input(meshed, name, rows, edit, texts):
    out = bad_case(meshed, name, rows, edit)
    for text in ("FOAM FATAL IO ERROR", "constant/dsmcProperties") + texts:
        assert text in out, (name, text, out[-1500:])
