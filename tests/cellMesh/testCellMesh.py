#!/usr/bin/python3
"""cellMesh on scratch cases of the paper's average cell (D = 16.8 um,
H = 7.9 um, nucleus 1/3 of the volume, 200 nm membrane), checked with an
independent reader of the .msh file:
  axisymmetric: only quadrilaterals in the regions and 2-node lines in the
    boundary groups; the exact group names; the section area pi (D/2) H/4 and
    the revolved volume (2/3) pi (D/2)^2 H to 3e-3 (coarse, 1 um) and
    1e-3 (fine, 0.5 um), the fine error at most half the coarse one
    (the inscribed polygons converge as h^2); nucleus volume fraction; membrane
    nodes on the layers+1 curves at distance k t/layers from the outer
    ellipse;
    the membrane area against Steiner's (P t - pi t^2)/4.
  quarter3D (the blast's default sizes 0.7/0.7/0.5 um, 2 membrane layers,
    and half of them) and full3D (0.8/0.8/0.6 um, 1 layer): only
    hexahedra (and quadrilateral faces), the group names incl. symmetry
    planes, the default's count in [1e4, 3e4], smallest scaled Jacobian
    > 0.2, volume to 3.5e-3 decreasing by half with the sizes, nucleus
    fraction to 0.5 %, membrane volume against the exact offset layer to
    5e-3, outer nodes on the spheroid, boundary faces on their planes;
    with the checker (2nd argument) the solid library reads each mesh
    (readGmsh, Mesh::check, volume).
  shapes3D: the same checks on quarters of a flat cell (D 20 um, H 4 um),
    a tall one (10 um, 8 um) and a 400 nm membrane with a coarse nucleus
    (1.5 um) in a fine cytoplasm (0.6 um).
  docExample: the dictionary printed in docs/userGuide/cellMesh.md
    meshes (axisymmetric and quarter3D, with the water box).
  scaledNucleus: nucleusShape scaledCell, axisymmetric.
  coarseContact: a contactSize above the regions' sizes meshes (adv33
    cm16: was SIGABRT).
  structuredSection: axisymmetric meshType structured (structuredCell's
    r-z section), nucleusShape scaledCell and centredSpheroid at h = 0.5
    and 0.25 um: the groups and element types of axisymmetric, every
    quadrilateral counter-clockwise with scaled Jacobian > 0.3, area and
    revolved volume to 1e-3, nucleus fraction to 0.5 %, nodes of the outer
    surface, the membrane's inner surface and the nucleus surface on the
    exact curves; halving h multiplies the element count by 3.4-4.6 and
    keeps the number of interior nodes not at 4 elements (block corners)
    fixed, at most 4 (gmsh's quads: 8-9 % of the interior nodes at 3 and
    8-9 % at 5).
  smoothSection: structuredSmoothing elliptic (issue 17 item 4), r-z
    scaledCell at h = 0.5 and 0.25 um, against none: the same element
    count, scaled Jacobian > 0.5, revolved volume to 1e-3, the nucleus
    surface's nodes on it; across the nucleus surface the largest kink of
    the grid lines below 8 deg and below half of none's, the spread
    (largest/smallest) of the first-element heights' ratio
    cytoplasm/nucleus below 0.7 of none's; the centred spheroid refused.
  scaledQuarter3D (the blast tutorial's 1.4/1.4/1 um, 1 layer, and
    0.7/0.7/0.5 um, 2 layers), scaledFull3D (0.8/0.8/0.6 um, 1 layer):
    nucleusShape scaledCell in 3D, the checks of quarter3D/full3D plus
    each region's volume within 1 % of the exact one (nucleus f V) and of
    the axisymmetric scaledCell mesh's (0.35 um), the nucleus in its
    semi-spheroid touching its top and rim, its base (area pi a_n^2 to
    1 %) in fixedBottom.
Usage: testCellMesh.py axisymmetric|quarter3D|full3D|shapes3D|docExample|
    scaledNucleus|scaledQuarter3D|scaledFull3D|coarseContact|
    structuredSection|smoothSection [solidReadCheck]"""
import os
import subprocess
import sys
import tempfile

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import msh
from neuronFsi.checks import Checks

root = os.path.abspath(os.path.join(os.path.dirname(__file__), "../.."))
D, H, t, f = 16.8e-6, 7.9e-6, 200e-9, 1.0/3.0
a = D/2
check = Checks()
# The solid library's reader check (tests/cellMesh/solidReadCheck.C), if
# given as the second argument
checker = sys.argv[2] if len(sys.argv) > 2 else None


def run(case, entries):
    os.makedirs(os.path.join(case, "system"), exist_ok=True)
    with open(os.path.join(case, "system/cellMeshDict"), "w") as d:
        d.write("FoamFile { version 2.0; format ascii; class dictionary;"
                " object cellMeshDict; }\n")
        for k, v in entries.items():
            d.write(f"{k} {v};\n")
    cmd = f". {root}/etc/bashrc && cellMesh -case {case}"
    p = subprocess.run(["bash", "-c", cmd], capture_output=True, text=True)
    if p.returncode != 0:
        print(p.stdout[-3000:], p.stderr[-3000:])
        sys.exit(f"cellMesh failed in {case}")
    return msh.read(os.path.join(case, "constant/cell.msh"))


def ellipseDistance(P):
    """Distance of points (r, z) to the outer quarter ellipse"""
    th = np.linspace(0, np.pi/2, 200001)
    E = np.stack([a*np.sin(th), H*np.cos(th)], 1)
    return np.array([np.min(np.hypot(*(E - p).T)) for p in P])


def quadMeasures(X, elems):
    A = V = 0.0
    for e in elems:
        x = np.array([X[n][:2] for n in e[3]])
        for j in (1, 2):
            u, w = x[j] - x[0], x[j + 1] - x[0]
            At = 0.5*(u[0]*w[1] - u[1]*w[0])
            A += abs(At)
            V += abs(2*np.pi*At*(x[0][0] + x[j][0] + x[j + 1][0])/3)
    return A, V


def axisymmetric():
    exactA = np.pi*a*H/4   # quarter ellipse, semi-axes D/2 and H
    exactV = 2.0/3.0*np.pi*a**2*H
    # Ramanujan's perimeter of the full ellipse (error ~1e-10 here)
    h = ((a - H)/(a + H))**2
    P = np.pi*(a + H)*(1 + 3*h/(10 + np.sqrt(4 - 3*h)))
    exactMem = (P*t - np.pi*t**2)/4
    errors = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, h0, layers in (("coarse", 1.0e-6, 1), ("fine", 0.5e-6, 2)):
            X, g = run(os.path.join(tmp, name), {
                "mode": "axisymmetric", "cellDiameter": D, "cellHeight": H,
                "membraneThickness": t, "membraneLayers": layers,
                "nucleusSize": h0, "cytoplasmSize": h0,
                "membraneSize": 0.8*h0, "contactRadius": 5e-6,
                "contactSize": 0.4*h0, "contactDepth": 1.5e-6})
            check(sorted(g) == sorted(["nucleus", "cytoplasm", "membrane",
                                       "fixedBottom", "axis",
                                       "outerSurface"]),
                  f"{name}: groups {sorted(g)}")
            types = {e[2] for r in ("nucleus", "cytoplasm", "membrane")
                     for e in g[r][1]}
            check(types == {3}, f"{name}: region element types {types}"
                  " (3 = 4-node quadrilateral)")
            btypes = {e[2] for r in ("fixedBottom", "axis", "outerSurface")
                      for e in g[r][1]}
            check(btypes == {1}, f"{name}: boundary element types {btypes}")
            A = {r: quadMeasures(X, g[r][1]) for r in
                 ("nucleus", "cytoplasm", "membrane")}
            areaA = sum(v[0] for v in A.values())
            volV = sum(v[1] for v in A.values())
            eA, eV = abs(areaA/exactA - 1), abs(volV/exactV - 1)
            errors[name] = max(eA, eV)
            tol = 3e-3 if name == "coarse" else 1e-3
            check(eA < tol and eV < tol, f"{name}: area error {eA:.2e},"
                  f" revolved volume error {eV:.2e} (< {tol})")
            frac = A["nucleus"][1]/volV
            ftol = 1e-2 if name == "coarse" else 5e-3
            check(abs(frac/f - 1) < ftol, f"{name}: nucleus volume fraction"
                  f" {frac:.5f} (1/3 within {ftol:.1%})")
            eM = abs(A["membrane"][0]/exactMem - 1)
            check(eM < 5e-3, f"{name}: membrane area error {eM:.2e} against"
                  " (P t - pi t^2)/4 (< 5e-3)")
            memNodes = sorted({n for e in g["membrane"][1] for n in e[3]})
            d = ellipseDistance([X[n][:2] for n in memNodes])
            lay = np.round(d/(t/layers))
            dev = np.max(np.abs(d - lay*t/layers))
            check(dev < 0.02*t and set(lay) == set(range(layers + 1)),
                  f"{name}: membrane nodes on {layers + 1} offset curves"
                  f" (max deviation {dev/t:.1e} t)")
            axis = [X[n][0] for e in g["axis"][1] for n in e[3]]
            bottom = [X[n][1] for e in g["fixedBottom"][1] for n in e[3]]
            outer = [X[n][:2] for e in g["outerSurface"][1] for n in e[3]]
            check(max(map(abs, axis)) < 1e-15 and
                  max(map(abs, bottom)) < 1e-15 and
                  np.max(ellipseDistance(outer)) < 1e-3*t,
                  f"{name}: axis at r = 0, fixedBottom at z = 0, "
                  "outerSurface on the ellipse")
    check(errors["fine"] < 0.5*errors["coarse"],
          f"error decreases with refinement ({errors['coarse']:.2e} ->"
          f" {errors['fine']:.2e})")


# Corner neighbours of the gmsh hexahedron (positive triple product) and
# the 2x2x2 Gauss points
hexCorner = [(1, 3, 4), (2, 0, 5), (3, 1, 6), (0, 2, 7),
             (7, 5, 0), (4, 6, 1), (5, 7, 2), (6, 4, 3)]
hexSign = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                    [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]])


def hexArrays(X, elems):
    return np.array([[X[n] for n in e[3]] for e in elems])


def scaledJacobian(x):
    """Smallest corner Jacobian / product of the corner edge lengths, per
    hexahedron (x: n x 8 x 3)"""
    sj = np.full(len(x), np.inf)
    for c, (i, j, k) in enumerate(hexCorner):
        e = [x[:, m] - x[:, c] for m in (i, j, k)]
        det = np.einsum("ni,ni->n", np.cross(e[0], e[1]), e[2])
        sj = np.minimum(sj, det/np.prod([np.linalg.norm(v, axis=1)
                                         for v in e], axis=0))
    return sj


def hexVolumes(x):
    """Exact volumes of trilinear hexahedra (2x2x2 Gauss), x: n x 8 x 3"""
    V = np.zeros(len(x))
    for q in hexSign/np.sqrt(3):
        n = 1 + q*hexSign                         # 8 x 3
        dN = 0.125*hexSign*np.stack([n[:, 1]*n[:, 2], n[:, 0]*n[:, 2],
                                     n[:, 0]*n[:, 1]], 1)
        V += np.linalg.det(np.einsum("nai,aj->nij", x, dN))
    return V


def membraneVolume():
    """Exact volume of the membrane: the semi-spheroid minus the solid of
    revolution inside the inner parallel surface (pi int r^2 dz, 2e5
    chords)"""
    th = np.linspace(0, np.pi/2, 200001)
    nr, nz = np.sin(th)/a, np.cos(th)/H
    nn = np.hypot(nr, nz)
    r = a*np.sin(th) - t*nr/nn
    z = H*np.cos(th) - t*nz/nn
    Vin = np.sum(np.pi/3*(r[1:]**2 + r[1:]*r[:-1] + r[:-1]**2)
                 * (z[:-1] - z[1:]))
    return 2.0/3.0*np.pi*a**2*H - Vin


def solidCheck(case, kind, tol):
    """The solid library reads the mesh (readGmsh + Mesh::check)"""
    p = subprocess.run([checker, os.path.join(case, "constant/cell.msh"),
                        kind, str(D), str(H), str(tol)],
                       capture_output=True, text=True)
    print("    " + p.stdout.strip().replace("\n", "\n    "))
    check(p.returncode == 0, f"solid library reads the {kind} mesh")


def cell3D(mode, sizes, maxCount=None, shape="centredSpheroid",
           record=None, volTol=3.5e-3):
    """Structured hexahedral cell at the given sizes (nucleus, cytoplasm,
    membrane [m], membrane layers) with the nucleus shape; the cell's and
    the membrane's volume errors below volTol; returns the volume errors
    (and appends each mesh's region volumes, of the whole cell, to
    record)"""
    quarter = mode == "quarter3D"
    share = 0.25 if quarter else 1.0
    errors = []
    with tempfile.TemporaryDirectory() as tmp:
        for hn, hc, hm, layers in sizes:
            name = f"{mode} {hn*1e6:g}/{hc*1e6:g}/{hm*1e6:g} um, {layers}"
            case = os.path.join(tmp, f"c{len(errors)}")
            X, g = run(case, {
                "mode": mode, "cellDiameter": D, "cellHeight": H,
                "membraneThickness": t, "membraneLayers": layers,
                "nucleusSize": hn, "cytoplasmSize": hc,
                "membraneSize": hm, "contactRadius": 0,
                "nucleusShape": shape})
            bnd = ["fixedBottom", "outerSurface"] + \
                (["symmetryX", "symmetryY"] if quarter else [])
            check(sorted(g) == sorted(["nucleus", "cytoplasm", "membrane"]
                                      + bnd), f"{name}: groups {sorted(g)}")
            regions = ("nucleus", "cytoplasm", "membrane")
            types = {e[2] for r in regions for e in g[r][1]}
            check(types == {5}, f"{name}: element types {types}"
                  " (5 = hexahedron)")
            ftypes = {e[2] for r in bnd for e in g[r][1]}
            check(ftypes == {3}, f"{name}: boundary face types {ftypes}")
            x = {r: hexArrays(X, g[r][1]) for r in regions}
            n = sum(len(v) for v in x.values())
            if maxCount and not errors:
                check(maxCount[0] <= n <= maxCount[1], f"{name}: {n}"
                      f" hexahedra in [{maxCount[0]}, {maxCount[1]}]")
            sj = min(scaledJacobian(v).min() for v in x.values())
            check(sj > 0.2, f"{name}: {n} hexahedra, min scaled Jacobian"
                  f" {sj:.3f} (> 0.2)")
            V = {r: hexVolumes(v).sum() for r, v in x.items()}
            tot = sum(V.values())
            exact = share*2.0/3.0*np.pi*a**2*H
            e = abs(tot/exact - 1)
            check(e < volTol, f"{name}: volume error {e:.2e}"
                  f" (< {volTol:g})")
            frac = V["nucleus"]/tot
            check(abs(frac/f - 1) < 5e-3, f"{name}: nucleus fraction"
                  f" {frac:.5f} (1/3 within 0.5 %)")
            eM = abs(V["membrane"]/(share*membraneVolume()) - 1)
            mTol = max(5e-3, volTol)
            check(eM < mTol, f"{name}: membrane volume error {eM:.2e}"
                  f" against the exact offset layer (< {mTol:g})")
            outer = np.array(sorted({n for e in g["outerSurface"][1]
                                     for n in e[3]}))
            P = np.array([X[k] for k in outer])
            rr = np.hypot(P[:, 0], P[:, 1])
            dev = np.max(np.abs((rr/a)**2 + (P[:, 2]/H)**2 - 1))
            check(dev < 1e-9, f"{name}: outerSurface nodes on the spheroid"
                  f" (max |(r/a)^2 + (z/H)^2 - 1| = {dev:.1e})")
            for nm, k in (("fixedBottom", 2), ("symmetryX", 0),
                          ("symmetryY", 1))[:3 if quarter else 1]:
                c = max(abs(X[m][k]) for e in g[nm][1] for m in e[3])
                check(c == 0, f"{name}: {nm} on its plane"
                      f" (max |x_{k}| = {c:.1e} m)")
            if shape == "scaledCell":
                scaledChecks(name, X, g, x, V, share)
            if record is not None:
                record.append({r: v/share for r, v in V.items()})
            if checker:
                solidCheck(case, "quarter" if quarter else "full", volTol)
            errors.append(e)
    return errors


def scaledRegionVolumes():
    """Exact volumes of the regions with the scaled nucleus: f V, the
    inner volume minus it, the membrane layer [m^3]"""
    V = 2.0/3.0*np.pi*a**2*H
    return {"nucleus": f*V, "cytoplasm": V - membraneVolume() - f*V,
            "membrane": membraneVolume()}


def scaledChecks(name, X, g, x, V, share):
    """nucleusShape scaledCell in 3D: each region's volume within 1 % of
    the exact one, the nucleus inside its semi-spheroid (semi-axes
    cbrt(f) a, cbrt(f) H) touching its top and its base rim, and its base
    (the disc r <= a_n, z = 0) in fixedBottom"""
    s3 = f**(1.0/3.0)
    an, hn = s3*a, s3*H
    for r, exact in scaledRegionVolumes().items():
        e = V[r]/(share*exact) - 1
        check(abs(e) < 1e-2, f"{name}: {r} volume {V[r]/share:.5e} m^3"
              f" (whole cell), exact {exact:.5e}, error {e:.2e} (< 1e-2)")
    P = x["nucleus"].reshape(-1, 3)
    rr, z = np.hypot(P[:, 0], P[:, 1]), P[:, 2]
    q = (rr/an)**2 + (z/hn)**2
    check(q.max() < 1 + 1e-9 and abs(z.max()/hn - 1) < 1e-9
          and abs(rr.max()/an - 1) < 1e-9 and z.min() == 0,
          f"{name}: nucleus in its semi-spheroid (max (r/a_n)^2 +"
          f" (z/h_n)^2 = {q.max():.12f}), 0 <= z <= {z.max():.4e} m,"
          f" r <= {rr.max():.4e} m (exact {hn:.4e}, {an:.4e})")
    nuc = {n for e in g["nucleus"][1] for n in e[3]}
    base = [e[3] for e in g["fixedBottom"][1] if set(e[3]) <= nuc]
    A = 0.0
    for f4 in base:
        p = np.array([X[n] for n in f4])
        A += 0.5*abs(np.cross(p[2] - p[0], p[3] - p[1])[2])
    exactA = share*np.pi*an**2
    check(abs(A/exactA - 1) < 1e-2, f"{name}: the nucleus's base in"
          f" fixedBottom ({len(base)} faces, area {A:.4e} m^2, disc"
          f" {exactA:.4e} m^2)")


def quarter3D():
    # The blast's default quarter (13,032 hexahedra) and a fine one
    e = cell3D("quarter3D", [(0.7e-6, 0.7e-6, 0.5e-6, 2),
                             (0.35e-6, 0.35e-6, 0.3e-6, 2)],
               maxCount=(10000, 30000))
    check(e[1] < 0.5*e[0], f"volume error decreases with refinement"
          f" ({e[0]:.2e} -> {e[1]:.2e})")


def shapes3D():
    """Other cells (flat, tall, thick membrane with a coarse nucleus):
    the same checks on quarters"""
    global D, H, t, a
    for D, H, t, sizes in (
            (20e-6, 4e-6, 200e-9, (0.5e-6, 0.5e-6, 0.5e-6, 2)),
            (10e-6, 8e-6, 200e-9, (0.4e-6, 0.4e-6, 0.4e-6, 2)),
            (16.8e-6, 7.9e-6, 400e-9, (1.5e-6, 0.6e-6, 1.0e-6, 1))):
        a = D/2
        print(f"cell D = {D*1e6:g} um, H = {H*1e6:g} um, t = {t*1e9:g} nm")
        cell3D("quarter3D", [sizes])


def docExample():
    """The dictionary of docs/userGuide/cellMesh.md (as printed, and with
    mode quarter3D) meshes the cell and the water box"""
    text = open(os.path.join(root, "docs/userGuide/cellMesh.md")).read()
    block = text.split("## Dictionary")[1].split("```")[1]
    for mode in ("axisymmetric", "quarter3D"):
        with tempfile.TemporaryDirectory() as case:
            os.makedirs(os.path.join(case, "system"))
            with open(os.path.join(case, "system/cellMeshDict"), "w") as d:
                d.write("FoamFile { version 2.0; format ascii; class"
                        " dictionary; object cellMeshDict; }\n")
                d.write(block.replace("mode                  axisymmetric;",
                                      f"mode {mode};"))
            p = subprocess.run(["bash", "-c", f". {root}/etc/bashrc &&"
                                f" cellMesh -case {case}"],
                               capture_output=True, text=True)
            heads = [open(os.path.join(case, "constant", f)).readline()
                     if os.path.exists(os.path.join(case, "constant", f))
                     else "" for f in ("cell.msh", "fluid.msh")]
            check(p.returncode == 0 and heads == ["$MeshFormat\n"]*2,
                  f"documented dictionary, mode {mode}: cell.msh and"
                  " fluid.msh written")


def full3D():
    cell3D("full3D", [(0.8e-6, 0.8e-6, 0.6e-6, 1)])


def scaledNucleus():
    """nucleusShape scaledCell: the nucleus is the cell scaled by cbrt(f),
    a semi-spheroid standing on the substrate (11.65 x 5.48 um)"""
    s = f**(1.0/3.0)
    an, hn = s*a, s*H
    with tempfile.TemporaryDirectory() as tmp:
        X, g = run(os.path.join(tmp, "scaled"), {
            "mode": "axisymmetric", "cellDiameter": D, "cellHeight": H,
            "nucleusVolumeFraction": f, "nucleusShape": "scaledCell",
            "membraneThickness": t, "membraneLayers": 1,
            "nucleusSize": 0.5e-6, "cytoplasmSize": 0.5e-6,
            "membraneSize": 0.4e-6, "contactRadius": 5e-6,
            "contactSize": 0.2e-6, "contactDepth": 1.5e-6})
        A = {r: quadMeasures(X, g[r][1]) for r in
             ("nucleus", "cytoplasm", "membrane")}
        volV = sum(v[1] for v in A.values())
        exactV = 2.0/3.0*np.pi*a**2*H
        eV = abs(volV/exactV - 1)
        check(eV < 1e-3, f"revolved cell volume error {eV:.2e} (< 1e-3)")
        exactN = 2.0/3.0*np.pi*an**2*hn
        eN = abs(A["nucleus"][1]/exactN - 1)
        check(eN < 2e-3, f"nucleus volume error {eN:.2e} against "
              "2/3 pi a_n^2 h_n (< 2e-3)")
        frac = A["nucleus"][1]/volV
        check(abs(frac/f - 1) < 5e-3, f"nucleus volume fraction {frac:.5f}")
        nuc = np.array([X[n][:2] for e in g["nucleus"][1] for n in e[3]])
        check(abs(nuc[:, 1].max()/hn - 1) < 1e-9
              and abs(nuc[:, 0].max()/an - 1) < 1e-9
              and abs(nuc[:, 1].min()) < 1e-15,
              f"nucleus spans r <= {nuc[:, 0].max():.4e} m, "
              f"0 <= z <= {nuc[:, 1].max():.4e} m (exact {an:.4e}, {hn:.4e})")
        # Nucleus nodes on its curved surface lie on the scaled ellipse
        q = (nuc[:, 0]/an)**2 + (nuc[:, 1]/hn)**2
        check(q.max() < 1 + 1e-9, f"nucleus inside its ellipse "
              f"(max {q.max():.12f})")
        bottomNodes = {n for e in g["fixedBottom"][1] for n in e[3]}
        nucNodes = {n for e in g["nucleus"][1] for n in e[3]}
        onBottom = [X[n][0] for n in bottomNodes & nucNodes]
        check(len(onBottom) > 2 and abs(max(onBottom)/an - 1) < 1e-9,
              f"the nucleus stands on fixedBottom ({len(onBottom)} nodes, "
              f"up to r = {max(onBottom):.4e} m)")


def structuredSection():
    """meshType structured in the axisymmetric mode (see the module)"""
    exactA = np.pi*a*H/4
    exactV = 2.0/3.0*np.pi*a**2*H
    with tempfile.TemporaryDirectory() as tmp:
        for shape in ("scaledCell", "centredSpheroid"):
            s = f**(1.0/3.0)
            an = s*a
            cn, zn = (s*H, 0.0) if shape == "scaledCell" else (s*H/2, H/2)
            counts = {}
            for h0, layers in ((0.5e-6, 1), (0.25e-6, 2)):
                name = f"{shape} {h0*1e6:g} um"
                X, g = run(os.path.join(tmp, f"{shape}{h0}"), {
                    "mode": "axisymmetric", "meshType": "structured",
                    "nucleusShape": shape, "cellDiameter": D,
                    "cellHeight": H, "nucleusVolumeFraction": f,
                    "membraneThickness": t, "membraneLayers": layers,
                    "nucleusSize": h0, "cytoplasmSize": h0,
                    "membraneSize": 0.8*h0, "contactRadius": 5e-6,
                    "contactSize": 0.4*h0, "contactDepth": 1.5e-6})
                check(sorted(g) == sorted(["nucleus", "cytoplasm",
                                           "membrane", "fixedBottom",
                                           "axis", "outerSurface"]),
                      f"{name}: groups {sorted(g)}")
                types = {e[2] for r in ("nucleus", "cytoplasm", "membrane")
                         for e in g[r][1]}
                btypes = {e[2] for r in ("fixedBottom", "axis",
                                         "outerSurface") for e in g[r][1]}
                check(types == {3} and btypes == {1},
                      f"{name}: element types {types}, boundary {btypes}")
                quads = {r: [e[3][k:k + 4] for e in g[r][1]
                             for k in range(0, len(e[3]), 4)]
                         for r in ("nucleus", "cytoplasm", "membrane")}
                sj = 1.0
                for q in (q for r in quads.values() for q in r):
                    x = np.array([X[n][:2] for n in q])
                    for i in range(4):
                        e1 = x[(i + 1) % 4] - x[i]
                        e2 = x[(i + 3) % 4] - x[i]
                        sj = min(sj, (e1[0]*e2[1] - e1[1]*e2[0])
                                 / (np.hypot(*e1)*np.hypot(*e2)))
                check(sj > 0.3, f"{name}: counter-clockwise, smallest "
                      f"scaled Jacobian {sj:.3f} (> 0.3)")
                A = {r: quadMeasures(X, g[r][1]) for r in quads}
                areaA = sum(v[0] for v in A.values())
                volV = sum(v[1] for v in A.values())
                eA, eV = abs(areaA/exactA - 1), abs(volV/exactV - 1)
                check(eA < 1e-3 and eV < 1e-3, f"{name}: area error "
                      f"{eA:.2e}, revolved volume error {eV:.2e} (< 1e-3)")
                frac = A["nucleus"][1]/volV
                check(abs(frac/f - 1) < 5e-3,
                      f"{name}: nucleus volume fraction {frac:.5f}")
                nodes = {r: {n for q in quads[r] for n in q} for r in quads}
                outer = [X[n][:2] for e in g["outerSurface"][1] for n in e[3]]
                dOut = np.max(ellipseDistance(outer))
                nucSurf = np.array([X[n][:2] for n in
                                    nodes["nucleus"] & nodes["cytoplasm"]])
                qn = (nucSurf[:, 0]/an)**2 + ((nucSurf[:, 1] - zn)/cn)**2
                memIn = [X[n][:2] for n in
                         nodes["membrane"] & nodes["cytoplasm"]]
                dIn = ellipseDistance(memIn)
                check(dOut < 1e-3*t and np.max(abs(qn - 1)) < 1e-9
                      and np.max(abs(dIn - t)) < 1e-3*t,
                      f"{name}: nodes on the outer surface (distance "
                      f"{dOut:.1e} m), the nucleus (|q - 1| "
                      f"{np.max(abs(qn - 1)):.1e}), the membrane's inner "
                      f"surface (|d - t| {np.max(abs(dIn - t)):.1e} m)")
                valence = {}
                for q in (q for r in quads.values() for q in r):
                    for n in q:
                        valence[n] = valence.get(n, 0) + 1
                boundary = {n for r in ("fixedBottom", "axis",
                                        "outerSurface")
                            for e in g[r][1] for n in e[3]}
                irregular = sum(1 for n, v in valence.items()
                                if n not in boundary and v != 4)
                counts[h0] = (sum(len(q) for q in quads.values()), irregular)
                print(f"{name}: {counts[h0][0]} quadrilaterals, "
                      f"{irregular} interior nodes not at 4 elements")
            (n1, i1), (n2, i2) = counts[0.5e-6], counts[0.25e-6]
            check(3.4 < n2/n1 < 4.6 and i1 == i2 and i2 <= 4,
                  f"{shape}: halving h: elements x{n2/n1:.2f} (3.4-4.6), "
                  f"irregular interior nodes {i1} -> {i2} (equal, <= 4)")


def scaledAxisymmetricVolumes(h):
    """Region volumes of revolution of the axisymmetric scaledCell mesh at
    the size h [m] (the 3D meshes' reference)"""
    with tempfile.TemporaryDirectory() as tmp:
        X, g = run(os.path.join(tmp, "axi"), {
            "mode": "axisymmetric", "cellDiameter": D, "cellHeight": H,
            "nucleusShape": "scaledCell", "membraneThickness": t,
            "membraneLayers": 2, "nucleusSize": h, "cytoplasmSize": h,
            "membraneSize": 0.8*h, "contactRadius": 0})
        return {r: quadMeasures(X, g[r][1])[1]
                for r in ("nucleus", "cytoplasm", "membrane")}


def scaled3D(mode, sizes, volTol):
    """nucleusShape scaledCell in 3D (the indentation's nucleus in the
    blast's cell): the checks of cell3D plus scaledChecks, and each
    region's volume within 1 % of the axisymmetric mesh's"""
    record = []
    cell3D(mode, sizes, shape="scaledCell", record=record, volTol=volTol)
    axi = scaledAxisymmetricVolumes(0.35e-6)
    exact = scaledRegionVolumes()
    print("region volumes [m^3] (whole cell): exact, axisymmetric 0.35 um,"
          " then the 3D meshes")
    for r in ("nucleus", "cytoplasm", "membrane"):
        print(f"    {r:10s} {exact[r]:.5e} {axi[r]:.5e} "
              + " ".join(f"{v[r]:.5e}" for v in record))
        for v in record:
            d = v[r]/axi[r] - 1
            check(abs(d) < 1e-2, f"{mode} {r}: 3D {v[r]:.5e} against"
                  f" axisymmetric {axi[r]:.5e} m^3 ({d:+.2e}, < 1e-2)")


def scaledQuarter3D():
    # The blast tutorial's sizes (1.4/1.4/1 um, 1 layer; cell and membrane
    # volume to 1 %), then the quarter3D test's (0.7/0.7/0.5 um, 2 layers;
    # 3.5e-3 as the centred spheroid's)
    scaled3D("quarter3D", [(1.4e-6, 1.4e-6, 1.0e-6, 1)], 1e-2)
    scaled3D("quarter3D", [(0.7e-6, 0.7e-6, 0.5e-6, 2)], 3.5e-3)


def scaledFull3D():
    scaled3D("full3D", [(0.8e-6, 0.8e-6, 0.6e-6, 1)], 3.5e-3)


def coarseContact():
    # a contactSize above the regions' sizes (adv33 cm16: gmsh's MathEval
    # could not parse "+ -..." and cellMesh aborted, SIGABRT): meshes, the
    # regions' sizes decide near the contact
    with tempfile.TemporaryDirectory() as tmp:
        X, g = run(os.path.join(tmp, "c"), {
            "mode": "axisymmetric", "cellDiameter": D, "cellHeight": H,
            "membraneThickness": t, "membraneLayers": 1,
            "nucleusVolumeFraction": 0.3333, "nucleusShape": "scaledCell",
            "nucleusSize": 0.8e-6, "cytoplasmSize": 0.8e-6,
            "membraneSize": 0.4e-6, "contactRadius": 5e-6,
            "contactSize": 2e-6, "contactDepth": 3e-6})
        types = {e[2] for r in ("nucleus", "cytoplasm", "membrane")
                 for e in g[r][1]}
        check(types == {3}, f"contactSize 2e-6 m: region element types "
              f"{types} (3 = 4-node quadrilateral)")


def interfaceKinks(X, g):
    """At each interior node of the nucleus surface with one edge into
    each region: the kink [deg] of the grid line crossing it (the angle
    between its cytoplasm edge and its nucleus edge continued) and the
    ratio of the two edges' lengths (cytoplasm over nucleus)"""
    q = {r: [e[3][k:k + 4] for e in g[r][1] for k in range(0, len(e[3]), 4)]
         for r in ("nucleus", "cytoplasm")}
    N = {r: {n for e in q[r] for n in e} for r in q}
    bnd = {n for r in ("fixedBottom", "axis", "outerSurface")
           for e in g[r][1] for n in e[3]}
    iface = (N["nucleus"] & N["cytoplasm"]) - bnd
    off = {}
    for r in q:
        for e in q[r]:
            for k in range(4):
                for x, y in ((e[k], e[(k + 1) % 4]), (e[(k + 1) % 4], e[k])):
                    if x in iface and y not in iface:
                        off.setdefault((x, r), set()).add(y)
    kinks, ratios = [], []
    for n in iface:
        c, m = off.get((n, "cytoplasm"), ()), off.get((n, "nucleus"), ())
        if len(c) != 1 or len(m) != 1:
            continue
        P = np.array(X[n][:2])
        u = np.array(X[next(iter(c))][:2]) - P
        v = P - np.array(X[next(iter(m))][:2])
        cs = u @ v/(np.linalg.norm(u)*np.linalg.norm(v))
        kinks.append(np.degrees(np.arccos(np.clip(cs, -1, 1))))
        ratios.append(np.linalg.norm(u)/np.linalg.norm(v))
    return np.array(kinks), np.array(ratios)


def smoothSection():
    """structuredSmoothing elliptic (see the module)"""
    s = f**(1.0/3.0)
    an, cn = s*a, s*H
    with tempfile.TemporaryDirectory() as tmp:
        for h0 in (0.5e-6, 0.25e-6):
            m = {}
            for smoothing in ("none", "elliptic"):
                name = f"scaledCell {h0*1e6:g} um, {smoothing}"
                X, g = run(os.path.join(tmp, f"{smoothing}{h0}"), {
                    "mode": "axisymmetric", "meshType": "structured",
                    "structuredSmoothing": smoothing,
                    "nucleusShape": "scaledCell", "cellDiameter": D,
                    "cellHeight": H, "nucleusVolumeFraction": f,
                    "membraneThickness": t, "membraneLayers": 1,
                    "nucleusSize": h0, "cytoplasmSize": h0,
                    "membraneSize": 0.8*h0, "contactRadius": 0})
                quads = [e[3][k:k + 4] for r in ("nucleus", "cytoplasm",
                                                 "membrane")
                         for e in g[r][1] for k in range(0, len(e[3]), 4)]
                sj = 1.0
                for qd in quads:
                    x = np.array([X[n][:2] for n in qd])
                    for i in range(4):
                        e1 = x[(i + 1) % 4] - x[i]
                        e2 = x[(i + 3) % 4] - x[i]
                        sj = min(sj, (e1[0]*e2[1] - e1[1]*e2[0])
                                 / (np.hypot(*e1)*np.hypot(*e2)))
                A = [quadMeasures(X, g[r][1]) for r in ("nucleus",
                                                         "cytoplasm",
                                                         "membrane")]
                eV = abs(sum(v[1] for v in A)/(2.0/3.0*np.pi*a**2*H) - 1)
                nuc = {n for e in g["nucleus"][1] for n in e[3]}
                cyt = {n for e in g["cytoplasm"][1] for n in e[3]}
                P = np.array([X[n][:2] for n in nuc & cyt])
                qn = np.max(abs((P[:, 0]/an)**2 + (P[:, 1]/cn)**2 - 1))
                k, r = interfaceKinks(X, g)
                m[smoothing] = (len(quads), sj, k.max(), r.max()/r.min())
                print(f"{name}: {len(quads)} quadrilaterals, smallest "
                      f"scaled Jacobian {sj:.3f}, revolved volume error "
                      f"{eV:.1e}, nucleus nodes |q - 1| {qn:.1e}; across "
                      f"the nucleus surface ({len(k)} nodes): largest "
                      f"kink {k.max():.2f} deg (median "
                      f"{np.median(k):.2f}), first-element heights "
                      f"cytoplasm/nucleus {r.min():.2f} to {r.max():.2f}")
                check(sj > 0.5 and eV < 1e-3 and qn < 1e-9,
                      f"{name}: scaled Jacobian {sj:.3f} (> 0.5), volume "
                      f"error {eV:.1e} (< 1e-3), nucleus nodes on the "
                      f"surface ({qn:.1e} < 1e-9)")
            n0, _, k0, r0 = m["none"]
            n1, _, k1, r1 = m["elliptic"]
            # measured (session 44, the preview's sizes 0.35-0.125 um):
            # largest kink 15-17 deg unsmoothed, 5.5-6.3 smoothed;
            # height-ratio spread 5.1 and 2.5-2.7
            check(n1 == n0 and k1 < 8 and k1 < 0.5*k0 and r1 < 0.7*r0,
                  f"scaledCell {h0*1e6:g} um: elliptic against none: the "
                  f"same {n1} elements ({n0}), largest kink {k1:.2f} deg "
                  f"(< 8 and < half of {k0:.2f}), height-ratio spread "
                  f"{r1:.2f} (< 0.7 of {r0:.2f})")
        # the centred spheroid is refused
        case = os.path.join(tmp, "centred")
        os.makedirs(os.path.join(case, "system"))
        with open(os.path.join(case, "system/cellMeshDict"), "w") as d:
            d.write("FoamFile { version 2.0; format ascii; class dictionary;"
                    " object cellMeshDict; }\nmode axisymmetric;\n"
                    "meshType structured;\nstructuredSmoothing elliptic;\n"
                    f"cellDiameter {D};\ncellHeight {H};\n"
                    "nucleusSize 5e-7;\ncytoplasmSize 5e-7;\n"
                    "membraneSize 4e-7;\ncontactRadius 0;\n")
        p = subprocess.run(["bash", "-c", f". {root}/etc/bashrc && "
                            f"cellMesh -case {case}"],
                           capture_output=True, text=True)
        check(p.returncode != 0 and "scaledCell only" in p.stdout + p.stderr,
              f"centredSpheroid with structuredSmoothing elliptic refused "
              f"(exit {p.returncode})")


{"axisymmetric": axisymmetric, "quarter3D": quarter3D,
 "coarseContact": coarseContact,
 "scaledQuarter3D": scaledQuarter3D, "scaledFull3D": scaledFull3D,
 "full3D": full3D, "shapes3D": shapes3D,
 "docExample": docExample, "scaledNucleus": scaledNucleus,
 "structuredSection": structuredSection,
 "smoothSection": smoothSection}[sys.argv[1]]()
print(f"testCellMesh {sys.argv[1]}: {len(check.failed)} failed")
sys.exit(check.exitStatus())
