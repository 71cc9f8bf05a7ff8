# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The MPPIC comparison's set-up, ours and stock MPPICFoam on Snider's
column (tutorials/solids/sniderSedimentation), shared by bench/mppic (the
cost of a parcel-step) and bench/memory (the bytes per parcel).

Both clouds get the same MPPIC submodels, set here with foamDictionary in
both dictionaries from one list (MPPIC_ENTRIES), whatever the tutorial's
own choice: packing explicit (HarrisCrighton: alphaPacked 0.6, pSolid 10,
beta 2, eps 1e-7; correctionLimitingMethod absolute, e 0.85), damping
none, isotropy stochastic (timeScaleModel isotropic, alphaPacked 0.6,
e 0.85), no stochastic collisions, no dispersion, walls rebound e 0.85
(localInteraction), gravity as a particle force.  Averaging: ours with
cachedDual (the project's cached copy of upstream's dual, same results)
and, as a third column, with dual; MPPICFoam with dual.

Ours runs the grains alone in vacuum (no gas, no carrier solve).  The
stock solver needs a carrier phase, made practically absent: air at rest
(U.air = 0, p = 0; walls noSlip / fixedFluxPressure), rho.air =
2.5e-3 kg/m^3 (1e-6 of the grains'), nu = 1e-5 m^2/s (mu = 2.5e-8 Pa s),
laminar, two-way coupled (semiImplicit momentum source) as in MPPICFoam's
column tutorial, whose fvSchemes/fvSolution (PIMPLE, 1 outer, 2 pressure
correctors, GAMG) are used.  Grain forces: gravity (buoyancy factor
1 - 1e-6) and ErgunWenYuDrag, MPPICFoam's usual drag.  At that density the
drag is negligible: its response time rho_p alpha_c d^2/((150 alpha_d/
alpha_c + 1.75 Re) mu) is about 100 s at alpha = 0.3 and 16 s at
alpha = 0.6, against a run of a few 0.01 s, so it changes the grains'
velocity by well under 1 % of the slip.  The carrier's fields are
interpolated to the parcels with `cell` (upstream's MPPICFoam tutorials
use the dearer cellPoint for U.air): the stock cloud does no more than it
must.  MPPICFoam still solves the carrier's momentum and pressure each
step (with the cloud's momentum source): that is part of its cost by
design.

Same parcels: MPPICFoam injects, with manualInjection at SOI 0
(parcelBasisType fixed, nParticle 749, d fixedValue 0.3 mm, U0 = 0), the
positions our initialiser wrote (0/lagrangian/grains/positions, legacy
"(x y z) cell" lines, copied to constant/kinematicCloudPositions with 17
significant digits): same points, same count.  Remaining differences:
upstream's manualInjection (SOI 0, so a zero injection period) moves each
new parcel over the whole first step before the step's motion moves the
cloud again, so MPPICFoam's first step applies gravity twice and its
cloud runs one step of free fall (9.8 mm/s) ahead of ours in velocity
(the first step is not timed); the isotropy model's random numbers are
different streams, so the two clouds follow the same flow statistically,
not parcel by parcel; ours carries more per-parcel properties (T, Cp,
surface accommodation) that it does not use in vacuum.
"""

import os
import shutil

from rmf import foam

TUTORIAL = os.path.join(foam.PROJECT_DIR, "tutorials", "solids", "sniderSedimentation")
STOCK_TUTORIAL = os.path.join(os.environ.get("FOAM_TUTORIALS", ""), "lagrangian",
                              "MPPICFoam", "column")
DT = 1e-3
RHO_CARRIER = 2.5e-3        # kg/m^3: 1e-6 of the grains' 2500
NU_CARRIER = 1e-5           # m^2/s
N_PARTICLE = 749
D_PARCEL = 3e-4             # m


_WALL = "{ type rebound; e 0.85; mu 0; }"

# The MPPIC set-up both clouds get (entry: value, set with foamDictionary)
MPPIC_ENTRIES = {
    "constantProperties/rho0": "2500",
    "subModels/dispersionModel": "none",
    "subModels/patchInteractionModel": "localInteraction",
    "subModels/localInteractionCoeffs":
        f"{{ patches ( sides {_WALL} bottom {_WALL} top {_WALL} ); }}",
    "subModels/packingModel": "explicit",
    "subModels/explicitCoeffs":
        "{ particleStressModel { type HarrisCrighton; alphaPacked 0.6;"
        " pSolid 10; beta 2; eps 1e-7; }"
        " correctionLimitingMethod { type absolute; e 0.85; } }",
    "subModels/dampingModel": "none",
    "subModels/isotropyModel": "stochastic",
    "subModels/stochasticCoeffs":
        "{ timeScaleModel { type isotropic; alphaPacked 0.6; e 0.85; } }",
    "subModels/stochasticCollisionModel": "none",
}

# Grain forces: ours in vacuum has gravity only; the stock cloud also drag
OUR_FORCES = "{ gravity; }"
STOCK_FORCES = "{ gravity; ErgunWenYuDrag { alphac alpha.air; } }"

HEADER = """\
/*--------------------------------*- C++ -*----------------------------------*\\
  rarefiedMultiphaseFoam: bench/mppic (stock MPPICFoam case)
\\*---------------------------------------------------------------------------*/
FoamFile
{{
    version     2.0;
    format      ascii;
    class       {cls};
    location    "{location}";
    object      {name};
}}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""

# Stock cloud: the skeleton; MPPIC_ENTRIES and STOCK_FORCES are set on it
STOCK_CLOUD = f"""\
solution
{{
    active          true;
    coupled         true;
    transient       yes;
    cellValueSourceCorrection off;
    interpolationSchemes
    {{
        rho.air         cell;
        U.air           cell;       // column tutorial: cellPoint (dearer)
        mu.air          cell;
    }}
    averagingMethod dual;
    integrationSchemes
    {{
        U               Euler;
    }}
    sourceTerms
    {{
        schemes
        {{
            U           semiImplicit 1;
        }}
    }}
}}

constantProperties
{{
    rho0            2500;
    alphaMax        0.9;        // MPPICFoam: carrier alpha >= 0.1 (carrier only)
}}

subModels
{{
    particleForces  {{}}
    injectionModels
    {{
        grains
        {{
            type            manualInjection;
            massTotal       0;
            parcelBasisType fixed;
            nParticle       {N_PARTICLE};
            SOI             0;
            positionsFile   "kinematicCloudPositions";
            U0              (0 0 0);
            sizeDistribution
            {{
                type        fixedValue;
                fixedValueDistribution
                {{
                    value   {D_PARCEL};
                }}
            }}
        }}
    }}
    heatTransferModel none;
    surfaceFilmModel none;
    radiation       off;
}}

cloudFunctions
{{
}}
"""

STOCK_TRANSPORT = f"""\
continuousPhase air;

rho.air         {RHO_CARRIER};  // 1e-6 of the grains' density

transportModel  Newtonian;
nu              {NU_CARRIER};
"""

STOCK_FIELD = """\
dimensions      {dims};

internalField   uniform {value};

boundaryField
{{
    ".*"
    {{
        {bc}
    }}
}}
"""

STOCK_CONTROL = """\
application     MPPICFoam;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         1;
deltaT          1;
writeControl    timeStep;
writeInterval   1;
purgeWrite      0;
writeFormat     ascii;
writePrecision  8;
writeCompression off;
timeFormat      general;
timePrecision   6;
runTimeModifiable false;
"""


def write_foam_file(path, cls, body):
    location = os.path.basename(os.path.dirname(path))
    with open(path, "w") as f:
        f.write(HEADER.format(cls=cls, location=location, name=os.path.basename(path)))
        f.write(body)


def set_controls(case, steps):
    """Run from t = 0 for steps steps of DT, writing nothing."""
    control = "system/controlDict"
    foam.set_entry(case, control, "startFrom", "startTime")
    foam.set_entry(case, control, "startTime", "0")
    foam.set_entry(case, control, "deltaT", f"{DT:g}")
    foam.set_entry(case, control, "endTime", f"{steps*DT:.6g}")
    foam.set_entry(case, control, "writeControl", "timeStep")
    foam.set_entry(case, control, "writeInterval", str(steps + 1))
    foam.set_entry(case, control, "runTimeModifiable", "false")


def set_mppic(case, cloud_dict, forces, averaging):
    for entry, value in MPPIC_ENTRIES.items():
        foam.set_entry(case, cloud_dict, entry, value)
    foam.set_entry(case, cloud_dict, "subModels/particleForces", forces)
    foam.set_entry(case, cloud_dict, "solution/averagingMethod", averaging)


def prepare_ours(build, steps, parcels=None):
    """Our case in build/ours-init, meshed and initialised, with the shared
    MPPIC set-up (and parcels parcels in the column instead of the
    tutorial's, if given)."""
    case = foam.copy_setup(TUTORIAL, os.path.join(build, "ours-init"))
    set_controls(case, steps)
    if parcels is not None:
        foam.set_entry(case, "system/grainsInitialiseDict",
                       "regions/column/nParcels", parcels)
    set_mppic(case, "constant/grainsProperties", OUR_FORCES, "cachedDual")
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case


def prepare_stock(build, ours, steps):
    """The stock MPPICFoam case in build/stock-init: our mesh, our initial
    parcel positions; returns it and the number of parcels."""
    case = os.path.join(build, "stock-init")
    if os.path.exists(case):
        shutil.rmtree(case)
    for sub in ("0", "constant", "system"):
        os.makedirs(os.path.join(case, sub))
    shutil.copytree(os.path.join(ours, "constant", "polyMesh"),
                    os.path.join(case, "constant", "polyMesh"))
    shutil.copy(os.path.join(ours, "constant", "g"), os.path.join(case, "constant"))
    for name in ("system/fvSchemes", "system/fvSolution",
                 "constant/turbulenceProperties.air"):
        shutil.copy(os.path.join(STOCK_TUTORIAL, name), os.path.join(case, name))

    positions = foam.read_positions(
        os.path.join(ours, "0", "lagrangian", "grains", "positions"))
    write_foam_file(os.path.join(case, "constant", "kinematicCloudPositions"),
                    "vectorField",
                    f"{len(positions)}\n(\n"
                    + "".join(f"({x:.17g} {y:.17g} {z:.17g})\n" for x, y, z in positions)
                    + ")\n")
    write_foam_file(os.path.join(case, "constant", "kinematicCloudProperties"),
                    "dictionary", STOCK_CLOUD)
    set_mppic(case, "constant/kinematicCloudProperties", STOCK_FORCES, "dual")
    write_foam_file(os.path.join(case, "constant", "transportProperties"),
                    "dictionary", STOCK_TRANSPORT)
    write_foam_file(os.path.join(case, "0", "U.air"), "volVectorField",
                    STOCK_FIELD.format(dims="[0 1 -1 0 0 0 0]", value="(0 0 0)",
                                       bc="type noSlip;"))
    write_foam_file(os.path.join(case, "0", "p"), "volScalarField",
                    STOCK_FIELD.format(dims="[0 2 -2 0 0 0 0]", value="0",
                                       bc="type fixedFluxPressure; value uniform 0;"))
    write_foam_file(os.path.join(case, "system", "controlDict"), "dictionary",
                    STOCK_CONTROL)
    set_controls(case, steps)
    return case, len(positions)
