# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Reading OpenFOAM ASCII files and running OpenFOAM applications on a case.

Only what the project's tests, benchmarks and plots need: internal fields
of volScalarField / volVectorField files written in ASCII, lists and
parcel positions, flat dictionary entries, the ASCII polyMesh (points,
faces, owner, neighbour, boundary), cell centres (from `postProcess -func
writeCellCentres`), and running an application with its output in
log.<application> (as RunFunctions does).
"""

import filecmp
import os
import re
import shutil
import subprocess

import numpy as np

PROJECT_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))

_NONUNIFORM = re.compile(rb"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(")
_UNIFORM = re.compile(rb"internalField\s+uniform\s+([^;]+);")


def _values(body, vector):
    """Numbers of an ASCII list body: (n,) scalars or (n, 3) vectors."""
    if vector:
        return np.array(body.replace(b"(", b" ").replace(b")", b" ").split(),
                        float).reshape(-1, 3)
    return np.array(body.split(), float)


def _uniform(value, n):
    """n copies of one ASCII value, scalar or "(x y z)"."""
    if value.startswith(b"("):
        return np.tile(_values(value, True)[0], (n, 1))
    return np.full(n, float(value))


def mesh_file(case, name):
    """Path of one file of the case's constant/polyMesh."""
    return os.path.join(case, "constant", "polyMesh", name)


def n_cells(case):
    """Number of cells of the case's mesh (from the owner file's note)."""
    with open(mesh_file(case, "owner"), "rb") as f:
        head = f.read(4096)
    m = re.search(rb"nCells:\s*(\d+)", head)
    if not m:
        raise ValueError(f"{case}: no nCells note in constant/polyMesh/owner")
    return int(m.group(1))


def read_field(path, ncells=None):
    """Internal field of an ASCII vol field file: shape (n,) or (n, 3).

    A uniform field needs ncells to be expanded.
    """
    with open(path, "rb") as f:
        text = f.read()
    m = _NONUNIFORM.search(text)
    if m:
        kind, n = m.group(1), int(m.group(2))
        start = m.end()
        if text[start:start + 1] in (b"\n", b"\r"):
            body = text[start:text.index(b"\n)", start)]
        else:   # a short list on one line: n(... ...);
            body = text[start:text.index(b";", start)].rstrip()[:-1]
        if kind not in (b"scalar", b"vector"):
            raise ValueError(f"{path}: unsupported List<{kind.decode()}>")
        values = _values(body, kind == b"vector")
        if len(values) != n:
            raise ValueError(f"{path}: expected {n} values, read {len(values)}")
        return values
    m = _UNIFORM.search(text)
    if m:
        if ncells is None:
            raise ValueError(f"{path}: uniform field, number of cells needed")
        value = m.group(1).strip()
        return _uniform(value, ncells)
    raise ValueError(f"{path}: no internalField found")


def times(case):
    """Names of a case's time directories, in time order."""
    found = []
    for name in os.listdir(case):
        try:
            found.append((float(name), name))
        except ValueError:
            pass
    return [name for _, name in sorted(found)]


def latest_time(case):
    """Name of the latest time directory of a case."""
    found = times(case)
    if not found:
        raise FileNotFoundError(f"{case}: no time directories")
    return found[-1]


def run(case, *args, log=None, np_=1):
    """Run an application on case; its output goes to case/log.<name>.

    np_ > 1 runs it with mpirun on that many ranks and -parallel.
    Raises CalledProcessError (with the log's tail) on failure.
    """
    app = os.path.basename(args[0])
    log = log or f"log.{app}"
    cmd = list(args)
    if np_ > 1:
        cmd = ["mpirun", "-np", str(np_)] + cmd + ["-parallel"]
    with open(os.path.join(case, log), "w") as out:
        proc = subprocess.run(cmd, cwd=case, stdout=out, stderr=subprocess.STDOUT)
    if proc.returncode != 0:
        with open(os.path.join(case, log)) as f:
            tail = "".join(f.readlines()[-30:])
        raise subprocess.CalledProcessError(proc.returncode, cmd, output=tail)
    return os.path.join(case, log)


# reconstructPar's options for every lagrangian field: without a selection
# v1912 leaves out fields of lists per parcel (the DEM contact histories,
# collisionRecords*; doc/physics.md#restart)
RECONSTRUCT_ALL = ("-lagrangianFields", '(".*")')


def run_solver(case, np_=1):
    """rarefiedMultiphaseFoam on an initialised case, serial or on np_
    ranks (decomposePar before, reconstructPar after, every lagrangian
    field: RECONSTRUCT_ALL); returns the log."""
    if np_ > 1:
        run(case, "decomposePar")
    log = run(case, "rarefiedMultiphaseFoam", np_=np_)
    if np_ > 1:
        run(case, "reconstructPar", *RECONSTRUCT_ALL)
    return log


def set_entry(case, dict_path, entry, value):
    """Set one entry of a case dictionary with foamDictionary."""
    subprocess.run(["foamDictionary", "-entry", entry, "-set", str(value),
                    os.path.join(case, dict_path)],
                   check=True, stdout=subprocess.DEVNULL)


def remove_entry(case, dict_path, entry):
    """Remove one entry of a case dictionary with foamDictionary."""
    subprocess.run(["foamDictionary", "-entry", entry, "-remove",
                    os.path.join(case, dict_path)],
                   check=True, stdout=subprocess.DEVNULL)


def substitute(path, pattern, replacement, count=1):
    """Replace a regular expression in a file's text, in place; raises
    RuntimeError where it is found fewer than count times.  For the
    dictionaries that #include others, which foamDictionary -set would
    write out expanded."""
    with open(path) as f:
        text = f.read()
    text, n = re.subn(pattern, replacement, text)
    if n < count:
        raise RuntimeError(f"{path}: {pattern!r} found {n} times, expected {count}")
    with open(path, "w") as f:
        f.write(text)


def get_entry(case, dict_path, entry):
    """Value of one entry of a case dictionary (foamDictionary -value)."""
    return subprocess.run(["foamDictionary", "-entry", entry, "-value",
                           os.path.join(case, dict_path)],
                          check=True, capture_output=True, text=True).stdout.strip()


def dsmc_tutorial(name):
    """Path of one of OpenFOAM's dsmcFoam tutorials."""
    return os.path.join(os.environ["FOAM_TUTORIALS"], "discreteMethods", "dsmcFoam", name)


def set_steps(case, steps):
    """Run a case from its start time for steps time steps, written once at
    the end (endTime = steps*deltaT; writeInterval the same in the case's
    writeControl: steps for timeStep, steps*deltaT otherwise)."""
    control = "system/controlDict"
    end = f"{steps*float(get_entry(case, control, 'deltaT')):.6g}"
    set_entry(case, control, "endTime", end)
    byStep = get_entry(case, control, "writeControl") == "timeStep"
    set_entry(case, control, "writeInterval", steps if byStep else end)
    set_entry(case, control, "startFrom", "startTime")


def copy_case(src, dst):
    """Fresh copy of a case directory (dst is replaced)."""
    if os.path.exists(dst):
        shutil.rmtree(dst)
    shutil.copytree(src, dst, symlinks=True)
    return dst


def copy_setup(src, dst):
    """Fresh copy of a case's set-up only: 0/, constant/, system/, without
    what blockMesh and the initialiser write there (dst is replaced)."""
    if os.path.exists(dst):
        shutil.rmtree(dst)
    products = shutil.ignore_patterns("polyMesh", "lagrangian", "uniform",
                                      "*SigmaTcRMax", "V", "C", "C?")
    for sub in ("0", "constant", "system"):
        if not os.path.isdir(os.path.join(src, sub)):
            # git keeps no empty directory: a case with no initial fields
            # has no 0/ in a fresh clone (its Allrun makes one)
            os.makedirs(os.path.join(dst, sub))
            continue
        shutil.copytree(os.path.join(src, sub), os.path.join(dst, sub),
                        ignore=products)
    return dst


def _mesh_field(case, time, name, func):
    """A field postProcess -func writes (name), written when missing."""
    path = os.path.join(case, time, name)
    if not os.path.exists(path):
        subprocess.run(["postProcess", "-func", func, "-time", time],
                       cwd=case, check=True, stdout=subprocess.DEVNULL)
    return read_field(path)


def cell_centres(case, time="0"):
    """Cell centres (n, 3) of a case (postProcess -func writeCellCentres)."""
    return _mesh_field(case, time, "C", "writeCellCentres")


def cell_volumes(case, time="0"):
    """Cell volumes (n,) of a case (postProcess -func writeCellVolumes)."""
    return _mesh_field(case, time, "V", "writeCellVolumes")


def read_list(path):
    """Values of an ASCII IOField file (e.g. a parcel property): (n,) or (n, 3)."""
    with open(path, "rb") as f:
        text = f.read()
    m = re.search(rb"\n(\d+)\s*\n\(", text)
    inline = re.search(rb"\n(\d+)\((.*)\)[ \t]*\n", text)  # short lists: n(a b ...)
    if not m and inline:
        values = _values(inline.group(2), b"(" in inline.group(2))
        if len(values) != int(inline.group(1)):
            raise ValueError(f"{path}: expected {inline.group(1)} values, read {len(values)}")
        return values
    if not m:
        m2 = re.search(rb"\n(\d+)\s*\{\s*([^}]*)\}", text)  # n{value}: all equal
        if m2:
            return _uniform(m2.group(2).strip(), int(m2.group(1)))
        raise ValueError(f"{path}: no list found")
    n = int(m.group(1))
    body = text[m.end():text.index(b"\n)", m.end())]
    values = _values(body, b"(" in body)
    if len(values) != n:
        raise ValueError(f"{path}: expected {n} values, read {len(values)}")
    return values


def write_list(path, values):
    """Replace the list of an ASCII lagrangian field file (labels, scalars
    or vectors), keeping its header."""
    with open(path) as f:
        text = f.read()
    head = text[:text.index("\n(\n", text.index("FoamFile"))]
    head = head[:head.rstrip().rindex("\n") + 1]
    if values.ndim == 1:
        body = "\n".join(f"{v:.17g}" for v in values)
    else:
        body = "\n".join(f"({u[0]:.17g} {u[1]:.17g} {u[2]:.17g})" for u in values)
    with open(path, "w") as f:
        f.write(f"{head}{len(values)}\n(\n{body}\n)\n")


def list_size(path):
    """Number of entries of an ASCII list file of any element type (a
    parcel property, or a list per parcel such as collisionRecords*):
    the entries at the outer level of its list, checked against the
    size written before it."""
    with open(path, "rb") as f:
        text = f.read()
    m = re.search(rb"\n(\d+)\s*([({])", text)
    if not m:
        raise ValueError(f"{path}: no list found")
    n = int(m.group(1))
    if m.group(2) == b"{":                  # n{value}: all equal
        return n
    depth, count, blank = 1, 0, True
    for c in text[m.end():]:
        if depth == 1 and not chr(c).isspace() and c != ord(")") and blank:
            count += 1
        blank = chr(c).isspace() and depth == 1
        depth += (c == ord("(")) - (c == ord(")"))
        if depth == 0:
            break
    if count != n:
        raise ValueError(f"{path}: {n} entries announced, {count} read")
    return n


def dict_text(path):
    """Text of an OpenFOAM dictionary file without its comments and its
    FoamFile header."""
    with open(path) as f:
        text = f.read()
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    return re.sub(r"FoamFile\s*\{[^}]*\}", " ", text)


def read_dict(path):
    """The 'keyword value;' entries of a dictionary file, values as
    strings: a flat reading (entries of sub-dictionaries included, the last
    of a repeated keyword kept; no #include or $macro expansion)."""
    return dict(re.findall(r"(\w+)\s+([^;{}\s]+)\s*;", dict_text(path)))


def read_boundary(case):
    """Patches of constant/polyMesh/boundary in file order: {name: {keyword:
    value as a string}} (type, nFaces, startFace, ...)."""
    text = dict_text(mesh_file(case, "boundary"))
    return {name: dict(re.findall(r"(\w+)\s+([^;]+?)\s*;", body))
            for name, body in re.findall(r"([^\s{}()]+)\s*\{([^{}]*)\}", text)}


def read_points(case):
    """Points (n, 3) of an ASCII constant/polyMesh."""
    return read_list(mesh_file(case, "points")).reshape(-1, 3)


def read_labels(case, name):
    """A label list of an ASCII constant/polyMesh (owner, neighbour) as integers."""
    return read_list(mesh_file(case, name)).astype(int)


def read_faces(case, start=0, count=None):
    """Faces of an ASCII constant/polyMesh, each an array of point labels:
    all of them, or count faces from start (a patch's)."""
    path = mesh_file(case, "faces")
    with open(path, "rb") as f:
        text = f.read()
    m = re.search(rb"\n(\d+)\s*\n\(", text)
    if not m:
        raise ValueError(f"{path}: no ASCII list")
    faces = re.findall(rb"\d+\(([^()]*)\)", text[m.end():text.rindex(b")")])
    stop = None if count is None else start + count
    return [np.array(face.split(), int) for face in faces[start:stop]]


_POSITION = re.compile(rb"\(([^()]*)\)\s+(-?\d+)")


def read_positions(path, cells=False):
    """Parcel positions (n, 3) of an ASCII lagrangian `positions` file,
    whose lines are "(x y z) celli" (OpenFOAM's legacy position format);
    with cells=True also the cell of each parcel, (n,) integers."""
    with open(path, "rb") as f:
        text = f.read()
    m = re.search(rb"\n(\d+)\s*\n\(", text)
    table = None
    if m:       # fast path: the list body as rows of 4 numbers
        body = text[m.end():text.index(b"\n)", m.end())].translate(None, b"()").split()
        if len(body) == 4*int(m.group(1)):
            table = np.array(body, float).reshape(-1, 4)
    if table is None:
        found = _POSITION.findall(text)
        table = np.array([p.split() + [c] for p, c in found], float).reshape(-1, 4)
    if cells:
        return table[:, :3], table[:, 3].astype(int)
    return table[:, :3]


def read_patch_field(path, patch):
    """Values of one patch of an ASCII vol field file: (faces,) or (faces, 3)
    (a uniform value as one face's)."""
    with open(path, "rb") as f:
        text = f.read()
    start = text.index(b"boundaryField")
    m = re.search(rb"\n\s*" + re.escape(patch.encode()) + rb"\s*\{", text[start:])
    if not m:
        raise ValueError(f"{path}: no patch {patch}")
    block = text[start + m.end():]
    block = block[:block.index(b"}")]
    v = re.search(rb"value\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\((.*)\)\s*;", block, re.S)
    if v:
        return _values(v.group(3), v.group(1) == b"vector")
    u = re.search(rb"value\s+uniform\s+([^;]+);", block)
    if not u:
        raise ValueError(f"{path}: patch {patch} has no value")
    return _uniform(u.group(1).strip(), 1)


_LOG_SEPARATORS = str.maketrans("/()", "   ")


def log_values(log, label):
    """Numbers after 'label =' on each matching line of a solver log
    (separated by blanks or '/'; a vector's brackets are dropped)."""
    pattern = re.compile(r"^\s*" + re.escape(label) + r"\s*=\s*(.*)$")
    rows = []
    with open(log) as f:
        for line in f:
            m = pattern.match(line)
            if m:
                rows.append([float(x) for x in m.group(1).translate(_LOG_SEPARATORS).split()])
    return np.array(rows)


_STEP_CRITERIA = re.compile(
    r"Gas step criteria since the last write: deltaT/\(mean collision time\) "
    r"largest (\S+) \((\d+) cells above 1\), cell transit \(\|U\| \+ 2 c_mp\) "
    r"deltaT/h largest (\S+) \((\d+) cells above 1(?:, the largest at [^;]*)?\); "
    r"share of a cell's kinetic energy in simulators crossing more than the "
    r"cell largest (\S+) \((\d+) cells "
    r"above ([0-9.eE+-]+)(?:, the largest at [^;]*)?\)")


def step_criteria(text):
    """The gas's step criteria of each write in a solver log's text
    (gasCloud's "Gas step criteria since the last write" line): per write
    (largest deltaT/tau, cells above 1, largest cell transit, cells above
    1, largest share of a cell's kinetic energy in simulators crossing
    more than the cell, cells above the share's limit, that limit)."""
    return [tuple(float(v) for v in row) for row in _STEP_CRITERIA.findall(text)]


_EXECUTION_TIME = re.compile(r"ExecutionTime = ([0-9.eE+-]+) s"
                             r"(?:\s+ClockTime = ([0-9.eE+-]+) s)?")


def execution_times(log, clock=False):
    """The CPU time [s] of each 'ExecutionTime = ... s' in a solver log
    (OpenFOAM's time line, and progressReport's); with clock, the
    'ClockTime = ... s' (wall time) that follows it instead, where one does.
    The project's one parser of these lines."""
    with open(log) as f:
        found = _EXECUTION_TIME.findall(f.read())
    if clock:
        return [float(c) for _, c in found if c]
    return [float(cpu) for cpu, _ in found]


def differing_files(a, b, rel="", equivalent=None):
    """Paths (relative to a and b) of the files under directories a and b
    that differ byte for byte or exist on one side only.  equivalent(fa,
    fb, rel), if given, may accept a pair that differs (rel: the pair's
    directory relative to a and b)."""
    cmp = filecmp.dircmp(a, b)
    diff = [os.path.join(rel, f) for f in cmp.left_only + cmp.right_only + cmp.funny_files]
    for f in cmp.common_files:
        fa, fb = os.path.join(a, f), os.path.join(b, f)
        if not filecmp.cmp(fa, fb, shallow=False):
            if equivalent is None or not equivalent(fa, fb, rel):
                diff.append(os.path.join(rel, f))
    for sub in cmp.common_dirs:
        diff += differing_files(os.path.join(a, sub), os.path.join(b, sub),
                                os.path.join(rel, sub), equivalent)
    return diff
