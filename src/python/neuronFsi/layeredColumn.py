"""The 1D answer of the blast scene's posed model on the axis: the water
column with the cell's layers in it (issue 17 item 1).

planeWave.column() computes the water-only column (rhoRiemannFoam). The
scene's cell is not water: along the axis the plane wave crosses the
membrane (the paper's quadratic volumetric law, eq. 2, p = -K (J - 1),
K = 2/d0, no energy), the cytoplasm and the nucleus (the solid's
Mie-Grueneisen law with adiabatic energy, their own rho0), each with the
neo-Hookean + Maxwell deviatoric stress of uniaxial strain. This module
solves that layered column independently of the scene's code (numpy):

    Lagrangian staggered finite volumes (von Neumann-Richtmyer): nodes
    carry u, cells carry rho = m/dz, e, p; leapfrog in time; the artificial
    viscosity q = rho (C2 du)^2 - C1 rho c du for du < 0 (du the velocity
    jump across the cell) spreads shocks over 3-4 cells; the energy
    equation de = -(p + q) dv (trapezoidal in p, closed form because the
    Mie-Grueneisen p is linear in e); the stress along the axis
    sigma_zz = -p - q + s_zz, s_zz = (2/3) mu (J^2 - 1)/J^(5/3) the
    deviatoric stress of the neo-Hookean law in uniaxial strain (F =
    diag(1, 1, J), mu = 2 C10 + sum mu_k: the Maxwell branches in their
    elastic limit, tau_k >= 0.01 s against a run of 150 ns).

    Layers: the vertical line x = r (r = 0: the axis) of the case's solid
    mesh (solidProperties mesh/file, gmsh, read by neuronFsi.msh), each
    element it crosses gives an interval of z and a region; water fills
    the rest up to the physical column's height Z. Interfaces fall on
    nodes (each layer in cells of at most dz).

    Boundaries: z = 0 the rigid substrate (u = 0). At the top the scene
    applies the pulse table P(t) at the fixed height Z (an Eulerian
    boundary, the water flows in through it), while the Lagrangian top
    moves down with the water by w(t) (0.17 um per 5 ns of 50 MPa). The
    top node is loaded with the pressure the plane z = Z had when the
    down-going characteristic through the top node left it: P(t - d), d =
    (Z - z_top)/(c - u) (c, u of the top cell and node), exact for the
    incident simple wave (the plateau is uniform and the rear is a
    rarefaction; the first shock starts at t = 0 where d = 0). The echo
    reaches the top after 2 Z/C0 (132 ns for 100 um) and its reflection
    the cell after about 200 ns: the top's treatment of it is outside a
    150 ns run's probes below 20 um.

    Probes: the water's probes are Eulerian (p + q and rho of the cell
    holding the height, linear between cell centres: what OpenFOAM's
    probes sample); the solid's probes are material points (the cells'
    fixed Lagrangian weights at their reference heights, as the solid's
    probes in postProcessing/solidProbes).

The result is a planeWave.PlaneWave (p [Pa], rho [kg/m^3], u [m/s], T [K]
per height), so neuronFsi.planeWave's measures compare a scene with it
(planeWave -layered).
"""

import hashlib
import math
import os
import subprocess

import numpy as np

from . import foamDict
from . import msh
from . import planeWave


class LayeredError(planeWave.PlaneWaveError):
    """A layered column that cannot be set up or run; the message says
    why."""


# the artificial viscosity: quadratic (von Neumann-Richtmyer) and linear
# coefficients [-]; chosen once on the water column against rhoRiemannFoam
# and the exact wall collision (docs/results/blastPlaneWave.md, "The
# layered reference"), not per case
C2 = 1.5
C1 = 0.25
CFL = 0.4


class MieGruneisen:
    """Water's law (paper eqs. 3-6, the same as src/eos/MieGruneisen.H,
    written again here):
        eta = 1 - rho0/rho
        pH  = rho0 C0^2 eta/(1 - s eta)^2
        p   = pH (1 - Gamma0 eta/2) + Gamma0 rho0 e,   T = T0 + e/Cv
    p gauge [Pa], e [J/kg] from the reference state."""

    kind = "mieGruneisen"

    def __init__(self, rho0, C0, s, Gamma0, Cv, T0, mu=0.0):
        self.rho0, self.C0, self.s, self.Gamma0 = rho0, C0, s, Gamma0
        self.Cv, self.T0, self.mu = Cv, T0, mu

    def cold(self, rho):
        """(p - Gamma0 rho0 e, its derivative d/d eta) [Pa]"""
        eta = 1 - self.rho0/rho
        d = 1 - self.s*eta
        k = self.rho0*self.C0**2
        pH = k*eta/d**2
        dpH = k*(1 + self.s*eta)/d**3
        g = 0.5*self.Gamma0
        return pH*(1 - g*eta), dpH*(1 - g*eta) - g*pH

    def pressure(self, rho, e):
        return self.cold(rho)[0] + self.Gamma0*self.rho0*e

    def soundSpeed2(self, rho, e):
        """c^2 = dp/drho at constant entropy [m^2/s^2]"""
        pc, dpc = self.cold(rho)
        p = pc + self.Gamma0*self.rho0*e
        return dpc*self.rho0/rho**2 + self.Gamma0*self.rho0*p/rho**2


class Quadratic:
    """The membrane's law (paper eq. 2): Psi_vol = (J - 1)^2/d0, p = -2 (J
    - 1)/d0 = K (1 - rho0/rho), K = 2/d0; no energy dependence."""

    kind = "quadratic"

    def __init__(self, rho0, d0, mu=0.0):
        self.rho0, self.K, self.mu = rho0, 2.0/d0, mu

    def pressure(self, rho, e):
        return self.K*(1 - self.rho0/rho) + 0*e

    def soundSpeed2(self, rho, e):
        return self.K*self.rho0/rho**2 + 0*e


def deviatoricZZ(mu, J):
    """s_zz [Pa] of the neo-Hookean law in uniaxial strain F = diag(1, 1,
    J): mu/J dev(b_bar)_zz = (2/3) mu (J^2 - 1)/J^(5/3)."""
    return (2.0/3.0)*mu*(J**2 - 1)/J**(5.0/3.0)


# ------------------------------------------------------------------ inputs

def _positive(path, where, value):
    v = value[-1] if isinstance(value, list) and value else value
    if isinstance(v, bool) or not isinstance(v, (int, float)) \
            or not (math.isfinite(v) and v > 0):
        raise LayeredError("%s: %s = %s: must be positive and finite"
                           % (path, where, value))
    return float(v)


def waterLaw(case):
    """The water's MieGruneisen of <case>/constant/thermophysicalProperties
    (mieGruneisen only)."""
    path = os.path.join(case, "constant", "thermophysicalProperties")
    try:
        d = foamDict.read(path)
    except (OSError, foamDict.DictError) as err:
        raise LayeredError("%s: %s" % (path, err))
    if d.get("equationOfState") != "mieGruneisen":
        raise LayeredError("%s: equationOfState %s: the layered column "
                           "solves mieGruneisen water only"
                           % (path, d.get("equationOfState")))
    c = d.get("mieGruneisenCoeffs")
    if not isinstance(c, dict):
        raise LayeredError("%s: no mieGruneisenCoeffs" % path)
    args = [_positive(path, "mieGruneisenCoeffs/" + k, c.get(k))
            for k in ("rho0", "C0", "s", "Gamma0", "Cv", "T0")]
    return MieGruneisen(*args)


def materials(case):
    """{region: its entries} of <case>/constant/solidProperties' materials,
    expanded by foamDictionary -expand (the #include of the parameter set
    and the case's overrides), and the solidProperties dictionary."""
    path = os.path.join(case, "constant", "solidProperties")
    out = subprocess.run(["foamDictionary", "-expand", path],
                         capture_output=True, text=True,
                         env=dict(os.environ, PWD=os.getcwd()))
    if out.returncode != 0:
        raise LayeredError("%s: foamDictionary -expand failed (%s)"
                           % (path, out.stderr.strip()))
    try:
        d = foamDict.parse(out.stdout, path)
    except foamDict.DictError as err:
        raise LayeredError(str(err))
    mats = d.get("materials")
    if not isinstance(mats, dict):
        raise LayeredError("%s: no materials sub-dictionary" % path)
    return mats, d


def regionLaw(path, region, m):
    """The law of one region's entries m (solidProperties materials/
    <region>): MieGruneisen or Quadratic, with mu = 2 C10 + sum mu_k."""
    where = "materials/%s/" % region
    if not isinstance(m, dict):
        raise LayeredError("%s: materials/%s is not a sub-dictionary"
                           % (path, region))
    rho0 = _positive(path, where + "rho0", m.get("rho0"))
    mu = 0.0
    if "C10" in m:
        mu = 2*float(m["C10"])
    k = 1
    while "mu%d" % k in m:
        mu += float(m["mu%d" % k])
        k += 1
    law = m.get("volumetric")
    if law == "mieGruneisen":
        return MieGruneisen(rho0, *[_positive(path, where + k, m.get(k))
                                    for k in ("C0", "s", "Gamma0", "Cv",
                                              "T0")], mu=mu)
    if law == "quadratic":
        d0 = m.get("d0")
        if isinstance(d0, bool) or not isinstance(d0, (int, float)) \
                or not (math.isfinite(d0) and d0 > 0):
            raise LayeredError("%s: %sd0 = %s: the layered column needs a "
                               "compressible quadratic law, d0 > 0 [1/Pa] "
                               "(d0 = 0 is incompressible)"
                               % (path, where, d0))
        return Quadratic(rho0, float(d0), mu=mu)
    raise LayeredError("%s: %svolumetric %s: not mieGruneisen or quadratic"
                       % (path, where, law))


def cellLayers(mshPath, r=0.0, scale=1.0):
    """[(z0, z1, region)] [m], bottom up: where the vertical line x = r [m]
    crosses the 2D regions of a gmsh mesh (x = r, y = z; r = 0: the
    elements with an edge on the axis). Adjacent intervals of one region
    are merged; the intervals must not overlap (a gap between them is
    water)."""
    try:
        X, groups = msh.read(mshPath)
    except msh.MshError as err:
        raise LayeredError(str(err))
    pieces = []
    for name, (dim, elements) in groups.items():
        if dim != 2:
            continue
        for _, _, _, tags in elements:
            P = np.array([X[t] for t in tags])[:, :2]*scale
            tol = 1e-9*max(np.ptp(P[:, 0]), np.ptp(P[:, 1]), 1e-30)
            zs = [p[1] for p in P if abs(p[0] - r) <= tol]
            for a, b in zip(P, np.roll(P, -1, axis=0)):
                if (a[0] - r)*(b[0] - r) < 0 and abs(a[0] - r) > tol \
                        and abs(b[0] - r) > tol:
                    zs.append(a[1] + (r - a[0])*(b[1] - a[1])/(b[0] - a[0]))
            if len(zs) >= 2 and max(zs) - min(zs) > tol:
                pieces.append((min(zs), max(zs), name))
    if not pieces:
        raise LayeredError("%s: no 2D element crosses the line x = %g m"
                           % (mshPath, r))
    pieces.sort()
    layers = [list(pieces[0])]
    for z0, z1, name in pieces[1:]:
        tol = 1e-9*max(z1, layers[-1][1])
        if z0 < layers[-1][1] - tol:
            raise LayeredError("%s: elements of %s and %s overlap on x = %g "
                               "m at z = %g m" % (mshPath, layers[-1][2],
                                                  name, r, z0))
        if name == layers[-1][2] and abs(z0 - layers[-1][1]) <= tol:
            layers[-1][1] = z1
        else:
            layers.append([z0, z1, name])
    return [tuple(l) for l in layers]


def caseLayers(case, r=0.0):
    """(layers [(z0, z1, region)], {region: law}, water law) of a blast
    case: the solid mesh's layers on the line x = r, each region's law from
    constant/solidProperties, the water's from thermophysicalProperties."""
    mats, props = materials(case)
    path = os.path.join(case, "constant", "solidProperties")
    try:
        mesh = props["mesh"]
        f = mesh["file"]
        scale = float(mesh.get("scale", 1))
    except (KeyError, TypeError, ValueError):
        raise LayeredError("%s: no mesh/file (and scale)" % path)
    f = f if os.path.isabs(f) else os.path.join(case, f)
    if not os.path.isfile(f):
        raise LayeredError("%s: mesh/file %s: no such file (run the case's "
                           "mesher first)" % (path, f))
    layers = cellLayers(f, r, scale)
    laws = {name: regionLaw(path, name, mats.get(name))
            for name in {l[2] for l in layers}}
    return layers, laws, waterLaw(case)


def wallCollision(law, p1):
    """The exact pressure [Pa] at a rigid wall hit by a shock of p1 [Pa]
    into <law>'s material at rest (p = 0, e = 0): the incident shock on
    the reference Hugoniot (Rankine-Hugoniot from rest), then the
    reflected shock that stops the material, from the jump conditions
        (u1 - 0)^2 = (p2 - p1)(v1 - v2),  e2 - e1 = (p1 + p2)(v1 - v2)/2
    and p2 = p(v2, e2) (bisection on v2). Returns (p2, incident particle
    speed u1 [m/s], rho1, rho2)."""
    v0 = 1/law.rho0

    def hug(v, vRef, pRef, eRef):
        # p on the Hugoniot from (vRef, pRef, eRef) at v: p(v, e) with e
        # from the jump; linear in p for the laws here
        a = law.pressure(1/v, 0.0)
        b = law.pressure(1/v, 1.0) - a          # dp/de
        return (a + b*(eRef + 0.5*pRef*(vRef - v)))/(1 - 0.5*b*(vRef - v))

    def bisect(f, lo, hi):
        flo = f(lo)
        for _ in range(200):
            mid = 0.5*(lo + hi)
            fm = f(mid)
            if (fm > 0) == (flo > 0):
                lo, flo = mid, fm
            else:
                hi = mid
        return 0.5*(lo + hi)

    v1 = bisect(lambda v: hug(v, v0, 0.0, 0.0) - p1, 0.7*v0, v0)
    u1 = math.sqrt(p1*(v0 - v1))
    e1 = 0.5*p1*(v0 - v1)
    v2 = bisect(lambda v: (hug(v, v1, p1, e1) - p1)*(v1 - v) - u1**2,
                0.6*v0, v1*(1 - 1e-12))
    return hug(v2, v1, p1, e1), u1, 1/v1, 1/v2


# ------------------------------------------------------------------ solver

class Column:
    """The layered column: layers [(z0, z1, law)] bottom up from z = 0
    (gaps and the part above the last layer up to Z filled with water),
    cells of at most dz [m]."""

    def __init__(self, layers, water, Z, dz):
        if not (math.isfinite(Z) and Z > 0 and math.isfinite(dz) and dz > 0):
            raise LayeredError("column height %g m and cell size %g m must "
                               "be positive and finite" % (Z, dz))
        spans, z = [], 0.0
        for z0, z1, law in layers:
            if z0 < z - 1e-12*Z or z1 > Z:
                raise LayeredError("layer [%g, %g] m overlaps another or "
                                   "leaves the column [0, %g] m"
                                   % (z0, z1, Z))
            if z0 > z + 1e-12*Z:
                spans.append((z, z0, water))
            spans.append((max(z0, z), z1, law))
            z = z1
        if z < Z:
            spans.append((z, Z, water))
        nodes, self.laws, self.groups = [0.0], [], []
        for z0, z1, law in spans:
            n = max(1, int(math.ceil((z1 - z0)/dz - 1e-9)))
            nodes += list(np.linspace(z0, z1, n + 1)[1:])
            # each span's cells, a slice (a law may hold several spans)
            self.groups.append((law, slice(len(self.laws),
                                           len(self.laws) + n)))
            self.laws += [law]*n
        self.spans = spans
        self.Z = Z
        self.z0 = np.array(nodes)
        self.N = len(self.laws)
        self.rho0 = np.array([l.rho0 for l in self.laws])
        self.mu = np.array([l.mu for l in self.laws])
        self.m = self.rho0*np.diff(self.z0)     # mass per area [kg/m^2]
        self.mNode = np.zeros(self.N + 1)
        self.mNode[:-1] += 0.5*self.m
        self.mNode[1:] += 0.5*self.m

    def _eval(self, rho, e):
        p = np.empty(self.N)
        c2 = np.empty(self.N)
        for law, k in self.groups:
            p[k] = law.pressure(rho[k], e[k])
            c2[k] = law.soundSpeed2(rho[k], e[k])
        if not (np.all(np.isfinite(c2)) and np.all(c2 > 0)):
            raise LayeredError("a state outside the laws' domain (c^2 <= 0 "
                               "or not finite) in the layered column")
        return p, c2

    def _energyStep(self, rho1, e0, p0, q, v0, v1):
        """e at the new volume (trapezoidal work, closed form for the
        Mie-Grueneisen laws, p linear in e; the others' p has no e)"""
        dv = v1 - v0
        e1 = np.empty_like(e0)
        for law, k in self.groups:
            if law.kind == "mieGruneisen":
                pc = law.cold(rho1[k])[0]
                G = law.Gamma0*law.rho0
                e1[k] = ((e0[k] - (0.5*(p0[k] + pc) + q[k])*dv[k])
                         / (1 + 0.5*G*dv[k]))
            else:
                e1[k] = e0[k] - (0.5*(p0[k] + law.pressure(rho1[k], 0))
                                 + q[k])*dv[k]
        return e1

    def run(self, pulse, endTime, eulerian=(), material=(), every=1,
            maxSteps=5e6, fixedTop=True):
        """Integrate to endTime [s] with the pulse table [(t [s], p [Pa])]
        applied at the plane z = Z; returns (t, P, RHO, U, T, E) arrays:
        P [Pa] = p + q (the normal stress's pressure, without the
        deviatoric part), rho, u (positive upwards), T (nan in a cell
        without temperature) and the specific energy at the probes, the
        eulerian heights then the material ones, every <every> steps.
        fixedTop False: the table applied on the moving top node itself
        (the error the delay removes; for the verification only)."""
        if not (math.isfinite(endTime) and endTime > 0):
            raise LayeredError("end time %g s must be positive and finite"
                               % endTime)
        tp = np.array([r[0] for r in pulse], dtype=float)
        vp = np.array([r[1] for r in pulse], dtype=float)
        N = self.N
        z = self.z0.copy()
        u = np.zeros(N + 1)          # at the half step
        e = np.zeros(N)
        rho = self.rho0.copy()
        p, c2 = self._eval(rho, e)
        q = np.zeros(N)
        J = np.ones(N)
        # material probes: fixed weights between cell centres
        zc0 = 0.5*(self.z0[1:] + self.z0[:-1])
        mat = []
        for h in material:
            if not 0 <= h <= self.Z:
                raise LayeredError("probe height %g m outside the column "
                                   "[0, %g] m" % (h, self.Z))
            k = int(np.clip(np.searchsorted(zc0, h) - 1, 0, N - 2))
            w = float(np.clip((h - zc0[k])/(zc0[k + 1] - zc0[k]), 0, 1))
            # a probe on a layer's boundary (or closer to it than half a
            # cell): the value of the cell holding it, not a mean across
            # two materials
            kk = int(np.clip(np.searchsorted(self.z0, h) - 1, 0, N - 1))
            if self.laws[k] is not self.laws[k + 1]:
                k, w = kk, 0.0
            mat.append((k, w))
        Tcell = np.array([getattr(l, "T0", np.nan) for l in self.laws])
        Cv = np.array([getattr(l, "Cv", np.nan) for l in self.laws])
        eul = np.asarray(eulerian, dtype=float)
        out = {k: [] for k in ("t", "p", "rho", "u", "T", "e")}

        kMat = np.array([k for k, _ in mat], dtype=int)
        wMat = np.array([w for _, w in mat])
        keys = ("p", "rho", "u", "T", "e")

        def record(t):
            zc = 0.5*(z[1:] + z[:-1])
            F = np.vstack((p + q, rho, 0.5*(u[1:] + u[:-1]), Tcell + e/Cv,
                           e))
            # the water's probes: linear between the cell centres around
            # the height (the end cells' value beyond them)
            k = np.clip(np.searchsorted(zc, eul) - 1, 0, N - 2)
            w = np.clip((eul - zc[k])/(zc[k + 1] - zc[k]), 0, 1)
            ve = F[:, k]*(1 - w) + F[:, k + 1]*w
            vm = F[:, kMat]*(1 - wMat) + F[:, np.minimum(kMat + 1, N - 1)]*wMat
            v = np.hstack((ve, vm))
            out["t"].append(t)
            for i, key in enumerate(keys):
                out[key].append(v[i])

        t = 0.0
        dtOld = None
        step = 0
        record(t)
        while t < endTime*(1 - 1e-12):
            dz = np.diff(z)
            # the longitudinal sound speed: the bulk one and the shear
            # modulus's 4/3 mu/rho (1e-7 of it in the cell; not in tests)
            c = np.sqrt(c2 + (4.0/3.0)*self.mu/rho)
            # q adds to the stiffness: the usual VNR bound
            dt = CFL*np.min(dz/(c + 2*C2**2*np.abs(np.minimum(
                np.diff(u), 0)) + 1e-30))
            dt = min(dt, endTime - t)
            if dtOld is None:
                dtOld = dt
            # the stress along the axis and the top's load
            s = deviatoricZZ(self.mu, J)
            S = p + q - s                   # -sigma_zz
            delay = (self.Z - z[-1])/(c[-1] - u[-1]) if fixedTop else 0.0
            Ptop = np.interp(t - delay, tp, vp, left=vp[0], right=vp[-1])
            a = np.zeros(N + 1)
            a[1:-1] = (S[:-1] - S[1:])/self.mNode[1:-1]
            a[-1] = (S[-1] - Ptop)/self.mNode[-1]
            u += 0.5*(dt + dtOld)*a
            u[0] = 0.0                      # the rigid substrate
            z1 = z + dt*u
            dz1 = np.diff(z1)
            if np.any(dz1 <= 0):
                raise LayeredError("a cell of the layered column inverted "
                                   "at t = %g s (time step %g s)" % (t, dt))
            rho1 = self.m/dz1
            du = np.diff(u)
            rhoH = 0.5*(rho + rho1)
            q = np.where(du < 0, rhoH*(C2*du)**2 - C1*rhoH*c*du, 0.0)
            e = self._energyStep(rho1, e, p, q, 1/rho, 1/rho1)
            rho, z = rho1, z1
            J = self.rho0/rho
            p, c2 = self._eval(rho, e)
            t += dt
            dtOld = dt
            step += 1
            if step > maxSteps:
                raise LayeredError("more than %d time steps to %g s: a "
                                   "coarser dz or a shorter end time"
                                   % (maxSteps, endTime))
            if step % every == 0 or t >= endTime*(1 - 1e-12):
                record(t)
        res = [np.array(out[k]) for k in ("t", "p", "rho", "u", "T", "e")]
        return res


def solve(case, heights, Z, endTime, dz=20e-9, r=0.0, material=(),
          water=False, maxSteps=1e6, fixedTop=True):
    """The layered column of <case> (its layers on the line x = r [m] of
    the solid mesh, its water, its pulse) to endTime [s], cells of at most
    dz [m]: a planeWave.PlaneWave at heights [m], those in material
    sampled at material points (the solid's probes), the others at fixed
    heights (the water's). water: no layers (the water-only column, for
    the verification against rhoRiemannFoam)."""
    for h in heights:
        if not 0 <= h <= Z:
            raise LayeredError("probe height %g m outside the column [0, %g]"
                               " m" % (h, Z))
    w = waterLaw(case)
    if water:
        layers = []
    else:
        cells, laws, w = caseLayers(case, r)
        layers = [(z0, z1, laws[name]) for z0, z1, name in cells]
    col = Column(layers, w, Z, dz)
    # its time steps, estimated before it runs (a lower bound: the
    # water's sound speed at rest, the smallest cell; issue 19's refusal
    # of planeWave's columns)
    steps = endTime/(CFL*np.diff(col.z0).min()/w.C0)
    if not steps <= maxSteps:
        raise LayeredError(
            "the layered column to %g s in cells of up to %g m takes about "
            "%.3g time steps (end time / (%g x the smallest cell / C0)), "
            "above the limit of %.3g (-maxSteps raises it; a shorter "
            "-endTime or a coarser -dz takes fewer)"
            % (endTime, dz, steps, CFL, maxSteps))
    pulse = planeWave.appliedPressure(case)
    mats = [h for h in heights if h in set(material)]
    euls = [h for h in heights if h not in set(material)]
    t, P, RHO, U, T, _ = col.run(pulse, endTime, euls, mats,
                                 fixedTop=fixedTop)
    order = euls + mats
    idx = [order.index(h) for h in heights]
    T = T[:, idx]
    wave = planeWave.PlaneWave(heights, t, P[:, idx], dz, Z, RHO[:, idx],
                               U[:, idx], None if np.isnan(T).any() else T)
    # the solid's probes are material points here (PlaneWave.solidAt)
    for h in mats:
        k = list(heights).index(h)
        wave.material[h] = {"p": wave.p[:, k], "rho": wave.rho[:, k],
                            "T": None if wave.T is None else wave.T[:, k],
                            "z": None}
    wave.layers = [(z0, z1, name) for z0, z1, name in
                   ([] if water else cells)]
    wave.cells = col.N
    return wave


def checkRunMesh(case):
    """Refuse to compare a run with a column made of another solid mesh:
    the SHA-1 of solidProperties' mesh/file against the digest the run
    recorded (the last time with a uniform/inputDigests, of the case or its
    processor0; foamTools::inputRecord hashes that file's bytes). Nothing
    to compare with when the run has no record."""
    _, props = materials(case)
    try:
        f = props["mesh"]["file"]
    except (KeyError, TypeError):
        raise LayeredError("%s/constant/solidProperties: no mesh/file" % case)
    path = f if os.path.isabs(f) else os.path.join(case, f)
    for where in (case, os.path.join(case, "processor0")):
        if not os.path.isdir(where):
            continue
        record = planeWave._recordedDigests(where)
        if not record:
            continue
        key = os.path.relpath(path, case)
        if key in record:
            with open(path, "rb") as fh:
                digest = hashlib.sha1(fh.read()).hexdigest()
            if digest != record[key]:
                raise LayeredError(
                    "%s changed since the run in %s (SHA-1 %s, the run "
                    "recorded %s): the layers would be another cell's. Mesh "
                    "it as the run had it, or run the case again"
                    % (path, case, digest, record[key]))
        return
