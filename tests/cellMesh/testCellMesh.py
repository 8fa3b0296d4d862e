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
  quarter3D: only hexahedra, groups incl. symmetry planes, quarter volume
    to 2e-3, nucleus fraction, boundary faces on their planes.
Usage: testCellMesh.py axisymmetric|quarter3D"""
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mshReader  # noqa: E402

root = os.path.abspath(os.path.join(os.path.dirname(__file__), "../.."))
D, H, t, f = 16.8e-6, 7.9e-6, 200e-9, 1.0/3.0
a = D/2
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


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
    return mshReader.read(os.path.join(case, "constant/cell.msh"))


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


def hexVolume(x):
    g = 1/np.sqrt(3)
    s = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                  [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]])
    V = 0.0
    for q in s*g:
        dN = np.empty((8, 3))
        for i in range(8):
            n = (1 + q*s[i])
            dN[i] = [s[i][0]*n[1]*n[2], s[i][1]*n[0]*n[2],
                     s[i][2]*n[0]*n[1]]
        V += np.linalg.det(0.125*(x.T @ dN))
    return V


def quarter3D():
    with tempfile.TemporaryDirectory() as tmp:
        X, g = run(os.path.join(tmp, "q"), {
            "mode": "quarter3D", "cellDiameter": D, "cellHeight": H,
            "membraneThickness": 0.4e-6, "membraneLayers": 1,
            "nucleusSize": 1.5e-6, "cytoplasmSize": 0.4e-6,
            "membraneSize": 1.0e-6, "contactRadius": 0})
    check(sorted(g) == sorted(["nucleus", "cytoplasm", "membrane",
                               "fixedBottom", "outerSurface", "symmetryX",
                               "symmetryY"]), f"groups {sorted(g)}")
    types = {e[2] for r in ("nucleus", "cytoplasm", "membrane")
             for e in g[r][1]}
    check(types == {5}, f"region element types {types} (5 = hexahedron)")
    ftypes = {e[2] for r in ("fixedBottom", "outerSurface", "symmetryX",
                             "symmetryY") for e in g[r][1]}
    check(ftypes == {3}, f"boundary face types {ftypes}")
    V = {r: sum(hexVolume(np.array([X[n] for n in e[3]]))
                for e in g[r][1]) for r in ("nucleus", "cytoplasm",
                                            "membrane")}
    check(min(V.values()) > 0, "all regions have positive volume")
    tot = sum(V.values())
    exact = 2.0/3.0*np.pi*a**2*H/4
    e = abs(tot/exact - 1)
    check(e < 2e-3, f"quarter volume error {e:.2e} (< 2e-3)")
    frac = V["nucleus"]/tot
    check(abs(frac/f - 1) < 1e-2, f"nucleus fraction {frac:.4f} (1 %)")
    for name, k in (("fixedBottom", 2), ("symmetryX", 0), ("symmetryY", 1)):
        c = max(abs(X[n][k]) for e in g[name][1] for n in e[3])
        check(c < 1e-15, f"{name} on its plane (max |x_{k}| = {c:.1e} m)")


{"axisymmetric": axisymmetric, "quarter3D": quarter3D}[sys.argv[1]]()
print(f"testCellMesh {sys.argv[1]}: {len(failures)} failed")
sys.exit(1 if failures else 0)
