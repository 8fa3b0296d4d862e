"""Damage indicators of the blast scene's solid, per region and per region
interface, from its results file solid.h5 (solidResults) and the solver's
interface maxima (postProcessing/solidInterfaces/interfaceMaxima.dat):
what pulseStudy (applications/utilities) tabulates and maps. The
solver's interface means over a fixed length (interfacePatches.dat, the
reported interface measure) are read by interfacePatches().

At each write of solid.h5, over the elements of a target (a region, or the
elements along an interface, either side, as the solver's interface
maxima take them):

    pressure         largest element pressure (+ compression) [Pa]
    vonMises         largest element von Mises stress [Pa]
    strain           largest principal Green-Lagrange strain E1 =
                     (lambda1^2 - 1)/2 [-], tension positive: the measure
                     of the stretch-injury thresholds (Lagrangian strain)
    strainRate       largest principal value in magnitude of
                     (E(t) - E(t - w))/w [1/s], the Green-Lagrange strain
                     tensor's rate averaged over the window w (e.g. 1 ns):
                     the raw rate's peak across a shock front grows as the
                     mesh is refined, its window average does not
    temperatureRise  largest element temperature rise [K] of the regions
                     whose volumetric law is Mie-Grueneisen (nucleus and
                     cytoplasm: the water law's adiabatic temperature of
                     the cell's own material, paper Fig. 9); NaN for a
                     target without one (the membrane's quadratic law has
                     no energy equation)

E is that of the deformation gradient F at the element's centre (r-z
quads: the in-plane gradient of the bilinear displacement and the hoop
stretch 1 + u_r/r of the centre; hexahedra: the trilinear gradient),
from the written nodal displacements; the solver's own F is the element's
volume average, which equals it for an affine displacement.

peak() and timeAbove() reduce a series to its largest value and to the
time it spends above a threshold (linear between samples).
"""

import math
import re

import numpy as np

from . import foamDict, msh, postProcessing
from .solidResults import SolidResults

INDICATORS = ("pressure", "vonMises", "strain", "strainRate",
              "temperatureRise")
UNITS = {"pressure": "Pa", "vonMises": "Pa", "strain": "-",
         "strainRate": "1/s", "temperatureRise": "K"}


class IndicatorError(Exception):
    pass


# Shape-function derivatives at the element's centre (gmsh node order)
_DQUAD = 0.25*np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])
_DHEX = 0.125*np.array([[-1.0, -1.0, -1.0], [1.0, -1.0, -1.0],
                        [1.0, 1.0, -1.0], [-1.0, 1.0, -1.0],
                        [-1.0, -1.0, 1.0], [1.0, -1.0, 1.0],
                        [1.0, 1.0, 1.0], [-1.0, 1.0, 1.0]])


def centreGradient(X, conn, u):
    """F at the centre of every element [nElements, 3, 3]: X [nNodes, 3]
    reference positions, conn [nElements, 4 or 8], u [nNodes, 3]. Quads
    are r-z sections (x = r, y = z): F_tt = 1 + u_r/r at the centre."""
    nen = conn.shape[1]
    if nen == 4:
        dim, dN = 2, _DQUAD
    elif nen == 8:
        dim, dN = 3, _DHEX
    else:
        raise IndicatorError("elements of %d nodes: only r-z quads (4) and "
                             "hexahedra (8)" % nen)
    Xe = X[conn][:, :, :dim]                    # [ne, nen, dim]
    ue = u[conn][:, :, :dim]
    J = np.einsum("nai,aj->nij", Xe, dN)        # dX/dxi
    dNdX = np.einsum("aj,nji->nai", dN, np.linalg.inv(J))
    G = np.einsum("nai,naj->nij", ue, dNdX)     # du/dX
    F = np.tile(np.eye(3), (len(conn), 1, 1))
    F[:, :dim, :dim] += G
    if dim == 2:
        r = Xe[:, :, 0].mean(axis=1)
        ur = ue[:, :, 0].mean(axis=1)
        F[:, 2, 2] = 1 + ur/r
    return F


def greenLagrange(F):
    """E = (F^T F - I)/2 of every F [n, 3, 3]."""
    return 0.5*(np.einsum("nki,nkj->nij", F, F) - np.eye(3))


def largestPrincipal(E):
    """The largest eigenvalue of every symmetric E [n, 3, 3]."""
    return np.linalg.eigvalsh(E)[:, -1]


def largestMagnitude(E):
    """The eigenvalue of largest magnitude's magnitude of every symmetric
    E [n, 3, 3]."""
    return np.abs(np.linalg.eigvalsh(E)).max(axis=1)


def interfaceElements(conn, region, a, b):
    """The elements of regions a or b with a node on an element of the
    other one (the solver's interfaceElements, src/fsi/solidDomain)."""
    inA = np.zeros(conn.max() + 1, bool)
    inB = np.zeros_like(inA)
    inA[conn[region == a].ravel()] = True
    inB[conn[region == b].ravel()] = True
    touchB = inB[conn].any(axis=1)
    touchA = inA[conn].any(axis=1)
    return ((region == a) & touchB) | ((region == b) & touchA)


def peak(y):
    """The largest value of y that is not NaN; NaN if there is none."""
    y = np.asarray(y, float)
    return float(np.nanmax(y)) if np.any(np.isfinite(y)) else math.nan


def timeAbove(t, y, level):
    """The time [s] y(t) spends above level, y linear between the samples
    (NaN samples: their intervals do not count)."""
    t = np.asarray(t, float)
    y = np.asarray(y, float) - level
    total = 0.0
    for k in range(len(t) - 1):
        a, b = y[k], y[k + 1]
        dt = t[k + 1] - t[k]
        if not (np.isfinite(a) and np.isfinite(b)):
            continue
        if a > 0 and b > 0:
            total += dt
        elif a > 0 or b > 0:
            total += dt*max(a, b)/abs(b - a)
    return total


def regionNames(case):
    """The solid's region names by region index: the physical groups of
    the case's gmsh mesh (solidProperties mesh/file), in the order of the
    solid library's region ids."""
    props = foamDict.read("%s/constant/solidProperties" % case)
    try:
        path = props["mesh"]["file"]
    except (KeyError, TypeError):
        raise IndicatorError("%s/constant/solidProperties: no mesh/file"
                             % case)
    path = path if path.startswith("/") else "%s/%s" % (case, path)
    try:
        names2 = msh.physicalNames(path, 2)
        names3 = msh.physicalNames(path, 3)
    except msh.MshError as err:
        raise IndicatorError(str(err))
    return names3 or names2, props


def thermalRegions(props, names):
    """The regions whose volumetric law is Mie-Grueneisen (they have a
    temperature)."""
    mats = props.get("materials", {})
    return {n for n in names if isinstance(mats.get(n), dict)
            and mats[n].get("volumetric") == "mieGruneisen"}


def targets(case):
    """(names, masks): the regions then the interfaces of
    solidProperties/interfaces ('a-b'), each a boolean mask over the
    elements, and which of them have a temperature."""
    names, props = regionNames(case)
    with SolidResults("%s/solid/solid.h5" % case) as f:
        conn = f.mesh("connectivity")
        region = f.mesh("region")
    out = {}
    for i, n in enumerate(names):
        out[n] = region == i
    for a, b in props.get("interfaces", []):
        if a not in names or b not in names:
            raise IndicatorError("%s/constant/solidProperties: interface "
                                 "(%s %s): regions are %s"
                                 % (case, a, b, " ".join(names)))
        out["%s-%s" % (a, b)] = interfaceElements(
            conn, region, names.index(a), names.index(b))
    hot = thermalRegions(props, names)
    thermal = np.isin(region, [names.index(n) for n in hot])
    return out, thermal


def series(case, window):
    """{target: {indicator: array over the writes}} and the write times
    [s] of solid.h5; the rate over window [s] (a whole number of write
    intervals: else IndicatorError), NaN where the window reaches before
    the first write."""
    masks, thermal = targets(case)
    with SolidResults("%s/solid/solid.h5" % case) as f:
        X = f.mesh("coordinates")
        conn = f.mesh("connectivity")
        steps = f.steps()
        t = np.array([f.time(k) for k in steps])
        n = len(steps)
        out = {m: {i: np.full(n, math.nan) for i in INDICATORS}
               for m in masks}
        E = {}                          # the writes within a window
        for j, k in enumerate(steps):
            p = f.field(k, "pressure")
            vm = f.field(k, "vonMises")
            dT = np.where(thermal, f.field(k, "temperatureRise"), math.nan)
            E[j] = greenLagrange(centreGradient(
                X, conn, f.field(k, "displacement")))
            for old in [i for i in E if t[i] < t[j] - window*(1 + 1e-6)]:
                del E[old]
            e1 = largestPrincipal(E[j])
            # the write a window earlier (the writes of adjustableRunTime
            # fall on multiples of the write interval)
            back = [i for i in E if abs(t[i] - (t[j] - window))
                    <= 1e-6*window]
            rate = largestMagnitude((E[j] - E[back[-1]])/window) \
                if back else None
            for m, mask in masks.items():
                s = out[m]
                s["pressure"][j] = p[mask].max()
                s["vonMises"][j] = vm[mask].max()
                s["strain"][j] = e1[mask].max()
                if rate is not None:
                    s["strainRate"][j] = rate[mask].max()
                s["temperatureRise"][j] = peak(dT[mask])
    if n > 1 and window > t[-1] - t[0]:
        raise IndicatorError("%s/solid/solid.h5: the strain-rate window %g s"
                             " is longer than the written times (%g to %g "
                             "s)" % (case, window, t[0], t[-1]))
    if n > 1 and all(np.isnan(out[m]["strainRate"]).all() for m in out):
        raise IndicatorError(
            "%s/solid/solid.h5: no two writes %g s apart: the strain-rate "
            "window must be a whole number of write intervals (writes at %s "
            "s)" % (case, window, " ".join("%g" % x for x in t[:4])))
    return t, out


def interfaceMaxima(case):
    """{interface: (t [s], pMax [Pa], vonMisesMax [Pa])} of every step, from
    postProcessing/solidInterfaces/interfaceMaxima.dat (over restarts)."""
    log = "solidInterfaces/interfaceMaxima.dat"
    d = postProcessing.series(case, log)
    names = [n.split(":", 1)[1] for n in postProcessing.names(case, log)
             if n.startswith("pMax:")]
    return {n: (d[:, 0], d[:, 1 + 2*k], d[:, 2 + 2*k])
            for k, n in enumerate(names)}


PATCH_LOG = "solidInterfaces/interfacePatches.dat"
PATCH_QUANTITIES = ("pPatch", "vonMisesPatch", "shearPatch",
                    "vonMisesPatchX", "vonMisesPatchY", "vonMisesPatchZ",
                    "pMax", "vonMisesMax", "shearMax")


def _wrote(case, log):
    """Whether the run wrote postProcessing/<log> (in any time segment)"""
    try:
        postProcessing.segments(case, log)
        return True
    except postProcessing.ColumnFileError:
        return False


def hasInterfacePatches(case):
    """Whether the run wrote postProcessing/solidInterfaces/*/
    interfacePatches.dat (a run of a build or case before it: no)"""
    return _wrote(case, PATCH_LOG)


def interfacePatches(case):
    """{interface: {quantity: array}} of every step, from
    postProcessing/solidInterfaces/interfacePatches.dat (over restarts):
    't' [s] and, per interface (membrane-cytoplasm, ..., membrane-fluid),
    the solver's largest mean over a fixed length of interface (the
    reported measure: pPatch, vonMisesPatch, shearPatch [Pa]; the von
    Mises patch's centre vonMisesPatchX/Y/Z [m]) and the element maxima
    (mesh-dependent: pMax, vonMisesMax, shearMax [Pa])."""
    d = postProcessing.series(case, PATCH_LOG)
    names = postProcessing.names(case, PATCH_LOG)
    out = {}
    for k, n in enumerate(names):
        if ":" not in n:
            continue
        q, iface = n.split(":", 1)
        if q not in PATCH_QUANTITIES:
            continue
        out.setdefault(iface, {"t": d[:, 0]})[q] = d[:, k]
    return out


PLACE_LOG = "solidInterfaces/interfacePlaces.dat"
PLACE_QUANTITIES = ("pAt", "vonMisesAt", "shearAt")


def hasInterfacePlaces(case):
    """Whether the run wrote postProcessing/solidInterfaces/*/
    interfacePlaces.dat (solidProperties interfacePlaces given)"""
    return _wrote(case, PLACE_LOG)


def interfacePlaces(case):
    """{interface: {place: {quantity: array}}} of every step, from
    postProcessing/solidInterfaces/interfacePlaces.dat (over restarts):
    per interface and fixed place (solidProperties interfacePlaces) the
    solver's mean over the patch around the interface's point nearest the
    place's point: pAt, vonMisesAt, shearAt [Pa]; 't' [s] in each place's
    dict, and 'centre' (the patch's centre (x, y, z) [m] the header
    states)."""
    d = postProcessing.series(case, PLACE_LOG)
    names = postProcessing.names(case, PLACE_LOG)
    out = {}
    for k, n in enumerate(names):
        m = re.match(r"(\w+)_(\w+):(\S+)$", n)
        if not m or m.group(1) not in PLACE_QUANTITIES:
            continue
        q, place, iface = m.groups()
        out.setdefault(iface, {}).setdefault(
            place, {"t": d[:, 0]})[q] = d[:, k]
    for line in postProcessing.header(case, PLACE_LOG):
        m = re.match(r"(\w+):(\S+): point \(.*\) m, patch centre "
                     r"\((\S+) (\S+) (\S+)\) m", line)
        if m and m.group(2) in out and m.group(1) in out[m.group(2)]:
            out[m.group(2)][m.group(1)]["centre"] = tuple(
                float(m.group(k)) for k in (3, 4, 5))
    return out


def patchLength(case):
    """The patch length [m] interfacePatches.dat's header states"""
    for seg in postProcessing.segments(case, PATCH_LOG)[:1]:
        with open(seg[1]) as f:
            head = f.readline()
        m = re.search(r"r-z: ([0-9.eE+-]+) m of arc", head)
        if m:
            return float(m.group(1))
    return float("nan")
