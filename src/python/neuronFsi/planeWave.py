"""The plane-wave answer of the blast scene, and a probe measured against it.

The cell has water's bulk response (Mie-Grueneisen, or the membrane's
quadratic law with water's bulk modulus) and shear moduli about 1e-7 of
it, and the column's side walls slip: to that order the pressure anywhere
in the coupled 2D or 3D scene is the 1D nonlinear plane wave of the water
column, the pulse applied on the top face z = Z and reflected by the rigid
substrate z = 0 (Jerusalem & Dao 2012, sec. 2.2.2; issue 17).

column() computes that wave with rhoRiemannFoam on a 1D column with the
scene's own thermophysicalProperties, schemes and top/bottom boundary
conditions (the 0/p, 0/U, 0/T entries of the patches `top` and `bottom`,
copied with foamDictionary), at a cell size the caller chooses: the
default 25 nm is ten times finer than the scene's finest water cell. The
fluid solver itself is verified against exact Mie-Grueneisen Riemann
solutions (tests/verification/shockTubes.py, pulseWall.sh);
converged() reports the change between two sizes, the reference's own
error bar.

A scene may end its water at a height z_in below the physical column
(issue 17 item 2): its top patch is then of type planeWaveInflow (0/p
entries columnHeight, the physical column's height Z, and pulse, the
table applied on the column's top face), and the boundary condition takes
the incoming wave from constant/inflowWave, the 1D column's p and u at
z_in written by writeInflow (planeWave -inflow). column() of such a case
runs the full column with the classic top (the pulse table on p, U and T
zeroGradient); setInflowBoundary() writes the top entries of 0/.

measures() gives the numbers issue 17 asks of a probe history p(t):
    arrival    first time p reaches half the applied pressure [s]
               (linear between samples)
    peak1ns    the largest 1-ns running mean of p [Pa] (window centred),
               over the whole history: near the substrate the incident
               pulse's tail overlaps the echo
    peakIncident  the same over the incident passage alone: window
               centres from the reference's arrival to 0.5 ns before the
               earlier of the pulse's end and the echo; None when empty
    plateau    the mean of p over the incident plateau [Pa]: from 1 ns
               after the reference's arrival to 1 ns before the earlier
               of the pulse's end and the reflection's return (2 z /
               (1.1 C0) after the arrival, on the early side); None when
               that window is under 1 ns
    impulse    int p dt [Pa s] from 2 ns before the reference's arrival to
               5 ns after the reflected pulse has passed (arrival + T +
               2 z / C0), cut to the data
The windows come from the reference, so the scene and the reference are
integrated over the same times.
"""

import glob
import hashlib
import math
import os
import re
import shutil
import subprocess
import tempfile

import numpy as np

from . import foamDict, ranges
from . import foamField
from . import postProcessing
from . import resultDigest
from . import script
from . import signals


class PlaneWaveError(Exception):
    """A column that cannot be set up or run; the message says why."""


def _fieldFile(case, field):
    """<case>/0/<field>, else <case>/0.orig/<field> (before restore0Dir)."""
    for d in ("0", "0.orig"):
        path = os.path.join(case, d, field)
        if os.path.isfile(path):
            return path
    raise PlaneWaveError("%s: no 0/%s or 0.orig/%s" % (case, field, field))


def _foamEnv():
    """The environment for an OpenFOAM application: PWD the working
    directory (ctest's WORKING_DIRECTORY leaves the shell's PWD, and
    OpenFOAM then prints a warning on stdout, into foamDictionary's
    value)."""
    return dict(os.environ, PWD=os.getcwd())


def _foamDictionary(path, entry, value=False):
    """An entry of a dictionary file as foamDictionary prints it (with
    value: its value only)."""
    out = subprocess.run(["foamDictionary", "-entry", entry]
                         + (["-value"] if value else []) + [path],
                         capture_output=True, text=True, env=_foamEnv())
    if out.returncode != 0:
        raise PlaneWaveError("%s: no %s (%s)"
                             % (path, entry, out.stderr.strip()))
    return out.stdout


def _patchEntry(path, patch):
    """boundaryField/<patch> of a field file as foamDictionary prints it,
    under the patch's own name: a patch matched by a pattern (".*" in the
    blast's 0/T) is printed under the pattern, and the column's field then
    held that pattern twice, for top and bottom (refused since fix19q as a
    keyword given twice in one scope)."""
    text = _foamDictionary(path, "boundaryField/" + patch).lstrip("\n")
    return patch + "\n" + text.split("\n", 1)[1]


INFLOW = "planeWaveInflow"     # the top patch type of a shortened scene
INFLOW_FILE = "constant/inflowWave"
# The water states the project takes as input (a pulse, an initial state)
# with the mieGruneisen law: |p| <= WATER_P_MAX [Pa], 0 < T <= WATER_T_MAX
# [K]; the reasons and the same numbers in src/eos/MieGruneisen.H
# (inputPMax, inputTMax; tests/python/testPlaneWave.py compares them)
WATER_P_MAX = 1e10
WATER_T_MAX = 1000.0
# the keywords of a constant/inflowWave (writeInflow; the C++ reader,
# planeWaveInflowWave, checks the same)
INFLOW_KEYWORDS = ("height", "columnHeight", "pulse", "dz", "ambientPressure",
                   "ambientTemperature", "thermoDigest", "rowsDigest", "data")


def _topP(case, patch):
    """(path, entry) of boundaryField/<patch> of 0/p (0.orig/p)."""
    path = _fieldFile(case, "p")
    try:
        top = foamDict.read(path)["boundaryField"][patch]
    except (KeyError, TypeError) as err:
        raise PlaneWaveError("%s: no boundaryField/%s (%s)"
                             % (path, patch, err))
    except foamDict.DictError as err:
        raise PlaneWaveError(str(err))
    if not isinstance(top, dict):
        raise PlaneWaveError("%s: boundaryField/%s is not a sub-dictionary"
                             % (path, patch))
    return path, top


def _table(path, where, value):
    """The rows [(t [s], p [Pa])] of a 'table ((t p) ...)' value."""
    try:
        kind, table = value
    except (TypeError, ValueError):
        raise PlaneWaveError("%s: %s is not a table ((t p) ...) [s Pa]"
                             % (path, where))
    if kind != "table":
        raise PlaneWaveError("%s: %s is %s, not a table" % (path, where, kind))
    try:
        rows = [(float(t), float(v)) for t, v in table]
    except (TypeError, ValueError):
        raise PlaneWaveError("%s: %s is not a table ((t p) ...) [s Pa]"
                             % (path, where))
    if not rows or not all(math.isfinite(t) and math.isfinite(v)
                           for t, v in rows):
        raise PlaneWaveError("%s: %s: the table is empty or holds a number "
                             "that is not finite" % (path, where))
    for i in range(1, len(rows)):
        if not rows[i][0] > rows[i - 1][0]:
            raise PlaneWaveError(
                "%s: %s: row %d at time %g s is not after row %d at %g s: "
                "the times of a table must increase"
                % (path, where, i + 1, rows[i][0], i, rows[i - 1][0]))
    return rows


def appliedPressure(case, patch="top"):
    """The pulse table [(t [s], p [Pa])] of the top face of the physical
    column, relative to the ambient internal pressure: the uniformValue
    table of 0/p (0.orig/p), or the pulse table of a planeWaveInflow top
    (applied at the top of its columnHeight)."""
    path, top = _topP(case, patch)
    if top.get("type") == INFLOW:
        if "pulse" not in top:
            raise PlaneWaveError("%s: boundaryField/%s (type %s) has no "
                                 "pulse table" % (path, patch, INFLOW))
        where = "boundaryField/%s/pulse" % patch
        rows = _table(path, where, top["pulse"])
    else:
        if "uniformValue" not in top:
            raise PlaneWaveError("%s: boundaryField/%s has no uniformValue "
                                 "table (nor type %s with a pulse table)"
                                 % (path, patch, INFLOW))
        where = "boundaryField/%s/uniformValue" % patch
        rows = _table(path, where, top["uniformValue"])
    if _law(case) == "mieGruneisen":
        for t, v in rows:
            if not abs(v) <= WATER_P_MAX:
                raise PlaneWaveError(
                    "%s: %s: the pressure %g Pa at %g s is outside the "
                    "water states the mieGruneisen law is used for: |p| <= "
                    "%g Pa (a fit for liquid water; the reasons in "
                    "src/eos/MieGruneisen.H, inputPMax)"
                    % (path, where, v, t, WATER_P_MAX))
    return rows


def _law(case):
    """The equationOfState of <case>'s constant/thermophysicalProperties
    (None if it cannot be read: its reader says why later)."""
    try:
        return foamDict.read(os.path.join(
            case, "constant", "thermophysicalProperties")).get(
                "equationOfState")
    except (OSError, foamDict.DictError):
        return None


def inflowColumnHeight(case, patch="top"):
    """The physical column's height [m] of a case whose top p is of type
    planeWaveInflow (its columnHeight entry); None for another top."""
    path, top = _topP(case, patch)
    if top.get("type") != INFLOW:
        return None
    if "columnHeight" not in top:
        raise PlaneWaveError("%s: boundaryField/%s (type %s) has no "
                             "columnHeight, the physical column's height "
                             "[m]" % (path, patch, INFLOW))
    Z = top["columnHeight"]
    if isinstance(Z, bool) or not isinstance(Z, (int, float)) \
            or not (math.isfinite(Z) and Z > 0):
        raise PlaneWaveError("%s: boundaryField/%s/columnHeight = %s: must "
                             "be a height [m], positive and finite"
                             % (path, patch, Z))
    return float(Z)


POINTS = "constant/polyMesh/points"
# OpenFOAM's probes write -VGREAT (-1e300) for a location outside the mesh
# (no cell holds it): never a pressure (issue 19, adv35 t42)
OUT_OF_MESH = 1e299


def meshTop(case):
    """The height [m] of the top of <case>'s fluid mesh (the largest y of
    constant/polyMesh/points for an r-z wedge, else z): where its water
    ends; None when the case has no mesh yet."""
    path = os.path.join(case, POINTS)
    if not os.path.isfile(path):
        return None
    try:
        pts = foamField.points(path)
    except (OSError, ValueError, AttributeError, IndexError) as err:
        raise PlaneWaveError("%s: cannot be read as a pointField (%s)"
                             % (path, err))
    if not len(pts) or not np.all(np.isfinite(pts)):
        raise PlaneWaveError("%s: no points, or a point that is not finite"
                             % path)
    return float(pts[:, 1 if isWedge(case) else 2].max())


def checkColumnHeight(case, Z, what="the column height"):
    """Refuse a column height Z [m] that differs from the case's physical
    column (relative 1e-9: the same number written another way): the
    columnHeight of a planeWaveInflow top, else the top of the case's
    mesh (relative 1e-6: the points are written with 6 or more digits),
    where the classic top applies the pulse (issue 19, adv35 t42: -Z
    30e-6 on a 20 um column blamed the scene)."""
    H = inflowColumnHeight(case)
    if H is not None:
        if abs(Z - H) > 1e-9*H:
            raise PlaneWaveError(
                "%s %g m differs from the case's physical column, %s: "
                "boundaryField/top/columnHeight = %g m (type %s): the pulse "
                "is applied at the top of that column" % (
                    what, Z, _fieldFile(case, "p"), H, INFLOW))
        return
    top = meshTop(case)
    if top is not None and abs(Z - top) > 1e-6*top:
        path, patch = _topP(case, "top")
        raise PlaneWaveError(
            "%s %g m differs from the case's water column, %g m (the top "
            "of its mesh, %s): its top patch (%s, boundaryField/top of type "
            "%s) applies the pulse there; give -Z %g or leave -Z out"
            % (what, Z, top, os.path.join(case, POINTS), path,
               patch.get("type"), top))


def caseColumnHeight(case, default=100e-6):
    """The physical column's height [m] of <case>: the columnHeight of a
    planeWaveInflow top, else the top of its mesh, else default (no mesh
    yet)."""
    H = inflowColumnHeight(case)
    if H is not None:
        return H
    top = meshTop(case)
    return default if top is None else top


def pulseShape(table):
    """(amplitude [Pa], duration [s]) of a pulse table: the largest value
    and the time between the half-amplitude crossings of the ramps."""
    t = np.array([r[0] for r in table])
    v = np.array([r[1] for r in table])
    amp = v.max()
    half = 0.5*amp
    k = int(np.argmax(v >= half))
    up = t[k - 1] + (half - v[k - 1])*(t[k] - t[k - 1])/(v[k] - v[k - 1])
    j = len(v) - 1 - int(np.argmax(v[::-1] >= half))
    down = t[j] + (half - v[j])*(t[j + 1] - t[j])/(v[j + 1] - v[j])
    return amp, down - up


_BLOCK_MESH = """FoamFile {{ version 2.0; format ascii; class dictionary;
    object blockMeshDict; }}
scale 1;
vertices
(
    (0 0 0) ({w} 0 0) ({w} {Z} 0) (0 {Z} 0)
    (0 0 {w}) ({w} 0 {w}) ({w} {Z} {w}) (0 {Z} {w})
);
blocks ( hex (0 1 2 3 4 5 6 7) (1 {n} 1) simpleGrading (1 1 1) );
boundary
(
    bottom {{ type wall; faces ((0 4 5 1)); }}
    top {{ type patch; faces ((3 2 6 7)); }}
    sides {{ type empty; faces ((0 3 7 4) (1 5 6 2) (0 1 2 3) (4 7 6 5)); }}
);
"""

_FIELD = """FoamFile {{ version 2.0; format ascii; class {cls};
    object {name}; }}
dimensions {dims};
internalField {internal};
boundaryField
{{
{top}
{bottom}
    sides {{ type empty; }}
}}
"""

_CONTROL = """FoamFile {{ version 2.0; format ascii; class dictionary;
    object controlDict; }}
application rhoRiemannFoam;
startFrom startTime; startTime 0; stopAt endTime; endTime {end};
deltaT 1e-13; writeControl adjustableRunTime; writeInterval {end};
purgeWrite 0; writeFormat binary; writePrecision 17;
writeCompression off; timeFormat general; timePrecision 8;
runTimeModifiable false; adjustTimeStep yes; maxCo {co}; maxDeltaT 1e-9;
maxSteps {steps};
functions
{{
    probes
    {{
        // the probes' own points (OpenFOAM's probes read the probe cell's
        // first tetrahedron's centroid in cells below 1e-15 m^3 per
        // tetrahedron: dz/8 off the height; movingMeshProbes.H)
        type movingMeshProbes; libs ("libfsi.so");
        writeControl timeStep; writeInterval 1;
        fields (p rho U T); interpolationScheme cellPoint;
        probeLocations ( {probes} );
    }}
}}
"""


class PlaneWave:
    """The 1D answer: times [s], p [Pa], rho [kg/m^3] and u [m/s] (the
    velocity along the column, positive upwards, away from the substrate)
    (one column per height; rho and u None for a reference file without
    them)."""

    def __init__(self, heights, t, p, dz, Z, rho=None, u=None, T=None):
        self.heights = np.asarray(heights, dtype=float)
        self.t = t
        self.p = p
        self.rho = rho
        self.u = u
        self.T = T
        self.dz = dz
        self.Z = Z
        # the histories at material points (the solid's probes): reference
        # height [m] -> {"p", "rho", "T" (None without temperatures), "z"
        # (its height [m] at each time, or None)}; materialHistory()
        self.material = {}
        # the digest of the column's constant/thermophysicalProperties as
        # rhoRiemannFoam recorded it (column(); None for a reference file)
        self.thermoDigest = None

    def _column(self, z):
        k = int(np.argmin(abs(self.heights - z)))
        if abs(self.heights[k] - z) > 1e-12:
            raise PlaneWaveError("height %g m not computed (heights %s m)"
                                 % (z, self.heights))
        return k

    def at(self, z):
        """p(t) [Pa] at height z [m] (one of the computed heights)."""
        return self.p[:, self._column(z)]

    def densityAt(self, z):
        """rho(t) [kg/m^3] at height z [m]"""
        if self.rho is None:
            raise PlaneWaveError("the reference has no densities (a "
                                 "reference.dat written before they were "
                                 "probed: compute it again)")
        return self.rho[:, self._column(z)]

    def temperatureAt(self, z):
        """T(t) [K] at height z [m]; None for a reference without
        temperatures"""
        return None if self.T is None else self.T[:, self._column(z)]

    def velocityAt(self, z):
        """u(t) [m/s] at height z [m], positive upwards"""
        if self.u is None:
            raise PlaneWaveError("the reference has no velocities (a "
                                 "reference.dat: compute the column)")
        return self.u[:, self._column(z)]

    def _material(self, z):
        for h, m in self.material.items():
            if abs(h - z) <= 1e-12:
                return m
        raise PlaneWaveError(
            "the reference has no history at the material point of "
            "reference height %g m (a solid probe follows its material, "
            "which the wave moves by up to a few tenths of a um; a "
            "reference.dat written before these were computed: compute it "
            "again)" % z)

    def solidAt(self, z):
        """p(t) [Pa] at the material point of reference height z [m]"""
        return self._material(z)["p"]

    def solidDensityAt(self, z):
        """rho(t) [kg/m^3] at the material point of reference height z"""
        return self._material(z)["rho"]

    def solidTemperatureAt(self, z):
        """T(t) [K] at the material point of reference height z (None
        without temperatures)"""
        return self._material(z)["T"]


def materialHistory(t, heights, p, rho, u, z0, T=None):
    """The history of the material point at reference height z0 [m] (its
    height at t[0]) in a 1D wave sampled at fixed heights [m] (sorted,
    around z0) at times t [s]: p, rho, u, T arrays (time, height). Its path
    dz/dt = u(z, t) by Heun's rule from sample to sample, u linear in z
    between the heights; p, rho and T linear in z at the path. Returns
    {"p", "rho", "T" (None if T is None), "z"}. A PlaneWaveError if the
    path leaves the heights (the band was too narrow).

    A solid probe is a material point (solid::PointProbe): it follows the
    matter, which the wave moves down by about P T/(rho0 C0) (0.17 um for
    50 MPa for 5 ns) and back with the echo; where the echo overlaps the
    pulse's tail the 1-ns peak depends on the height (5 ns pulse at 4.1
    um: +2.6 % at the material point; docs/results/blastPlaneWave.md,
    "The layered reference" and "The 5 ns von Mises")."""
    t = np.asarray(t, dtype=float)
    H = np.asarray(heights, dtype=float)
    z = np.empty(len(t))
    z[0] = z0
    for n in range(len(t) - 1):
        dt = t[n + 1] - t[n]
        a = np.interp(z[n], H, u[n])
        b = np.interp(z[n] + dt*a, H, u[n + 1])
        z[n + 1] = z[n] + 0.5*dt*(a + b)
    if z.min() < H[0] - 1e-15 or z.max() > H[-1] + 1e-15:
        k = int(np.argmax((z < H[0]) | (z > H[-1])))
        raise PlaneWaveError(
            "the material point of reference height %g m is at %g m at t = "
            "%g s, outside the heights sampled around it [%g, %g] m"
            % (z0, z[k], t[k], H[0], H[-1]))
    # linear in z at the path: the bracketing heights' weights per time
    k = np.clip(np.searchsorted(H, z) - 1, 0, len(H) - 2)
    w = (z - H[k])/(H[k + 1] - H[k])
    rows = np.arange(len(t))

    def at(f):
        return (None if f is None else
                (1 - w)*f[rows, k] + w*f[rows, k + 1])

    return {"p": at(p), "rho": at(rho), "T": at(T), "z": z}


# the band of fixed heights sampled around a material point: its largest
# displacement is about P T/(rho0 C0) (a pulse P for T down, the echo
# back up): this many times that on either side, at least MATERIAL_SPACING
# apart (cells of 25 nm: 50 nm; the paths' fronts span 3-4 cells)
MATERIAL_MARGIN = 1.5
MATERIAL_SPACING = 50e-9


def materialBand(z0, amplitude, duration, impedance, dz, Z):
    """Fixed heights [m] around the reference height z0 [m] that hold the
    path of its material point in a pulse of amplitude [Pa] for duration
    [s] in water of impedance rho0 C0 [kg/m^2/s] (column of cells dz [m],
    height Z [m]): spaced max(dz, MATERIAL_SPACING) (a multiple of dz).
    A PlaneWaveError for a pulse that is no compression."""
    if not (amplitude > 0 and duration > 0 and impedance > 0):
        raise PlaneWaveError(
            "the material point's band needs a compressive pulse and a "
            "positive impedance (pulse %g Pa for %g s, rho0 C0 %g kg/m^2/s)"
            % (amplitude, duration, impedance))
    step = dz*max(1, int(math.ceil(MATERIAL_SPACING/dz - 1e-9)))
    reach = MATERIAL_MARGIN*amplitude*duration/impedance + 2*step
    n = int(math.ceil(reach/step))
    return [z0 + i*step for i in range(-n, n + 1) if 0 < z0 + i*step < Z]


def uniaxialResponse(t, rho, rho0, mu0, branches=()):
    """The exact solid response of a material point carried by the plane
    wave: uniaxial strain along the wave, F = diag(1, 1, lambda) with
    lambda = J = rho0/rho(t) (the cell's nucleus and cytoplasm have the
    water's equation of state, so their density history is the water's).
    Returns (strain_z, vonMises): strain_z = ln(lambda) [-] and the von
    Mises stress [Pa] of the isochoric neo-Hookean part (mu0 = 2 C10) and
    the Maxwell branches (mu_k, tau_k), each relaxing as a linear Maxwell
    element on the same isochoric strain measure (exact in the elastic
    limit tau_k >> the run, which is the blast's: tau >= 0.01 s):

        sigma_dev = mu/J dev(b_bar),  b_bar = J^(-2/3) diag(1, 1, lambda^2)
        von Mises = mu |lambda^2 - 1| / J^(5/3)        (J = lambda)

    (Holzapfel 2000, sec. 6.5; the uniaxial-strain closed form). t [s],
    rho [kg/m^3] arrays; rho0 [kg/m^3]; mu0, mu_k [Pa]; tau_k [s]."""
    t = np.asarray(t, dtype=float)
    lam = rho0/np.asarray(rho, dtype=float)
    s = (lam**2 - 1)/lam**(5.0/3.0)
    total = mu0*s
    for mu, tau in branches:
        h = np.zeros_like(s)
        for k in range(1, len(s)):
            dt = t[k] - t[k - 1]
            h[k] = (np.exp(-dt/tau)*h[k - 1]
                    + mu*np.exp(-0.5*dt/tau)*(s[k] - s[k - 1]))
        total = total + h
    return np.log(lam), np.abs(total)


def soundSpeedAtRest(case):
    """The sound speed [m/s] of <case>'s water at rest, from
    constant/thermophysicalProperties: C0 for mieGruneisen (p = 0 at rho0),
    sqrt(gamma (gamma - 1) Cv T) for idealGas and stiffenedGas with T the
    uniform internalField of 0/T."""
    path = os.path.join(case, "constant", "thermophysicalProperties")
    try:
        d = foamDict.read(path)
    except (OSError, foamDict.DictError) as err:
        raise PlaneWaveError("%s: %s" % (path, err))
    law = d.get("equationOfState")
    coeffs = d.get("%sCoeffs" % law)

    def number(key, where, value):
        v = value[-1] if isinstance(value, list) and value else value
        if isinstance(v, bool) or not isinstance(v, (int, float)) \
                or not (math.isfinite(v) and v > 0):
            raise PlaneWaveError("%s: entry '%s' = %s: must be positive and "
                                 "finite" % (where, key, value))
        return float(v)

    if not isinstance(coeffs, dict):
        raise PlaneWaveError("%s: no %sCoeffs (equationOfState %s)"
                             % (path, law, law))
    if law == "mieGruneisen":
        return number("C0", path, coeffs.get("C0"))
    if law in ("idealGas", "stiffenedGas"):
        Tpath = _fieldFile(case, "T")
        text = _foamDictionary(Tpath, "internalField", True).split()
        if len(text) != 2 or text[0] != "uniform":
            raise PlaneWaveError("%s: the internalField must be uniform "
                                 "(the column's sound speed at rest)" % Tpath)
        try:
            T = float(text[1])
        except ValueError:
            T = text[1]
        g = number("gamma", path, coeffs.get("gamma"))
        return math.sqrt(g*(g - 1)*number("Cv", path, coeffs.get("Cv"))
                         * number("internalField", Tpath, T))
    raise PlaneWaveError("%s: equationOfState %s: not mieGruneisen, "
                         "stiffenedGas or idealGas" % (path, law))


def impedanceAtRest(case):
    """rho0 C0 [kg/m^2/s] of <case>'s water at rest (constant/
    thermophysicalProperties, equationOfState mieGruneisen: the solid's
    probes are in a Mie-Grueneisen water)."""
    path = os.path.join(case, "constant", "thermophysicalProperties")
    try:
        d = foamDict.read(path)
    except (OSError, foamDict.DictError) as err:
        raise PlaneWaveError("%s: %s" % (path, err))
    rho0 = (d.get("mieGruneisenCoeffs") or {}).get("rho0") \
        if d.get("equationOfState") == "mieGruneisen" else None
    if isinstance(rho0, bool) or not isinstance(rho0, (int, float)) \
            or not (math.isfinite(rho0) and rho0 > 0):
        raise PlaneWaveError(
            "%s: the solid probes' material points need the water's "
            "mieGruneisenCoeffs rho0 [kg/m^3], positive and finite (found "
            "equationOfState %s, rho0 %s)"
            % (path, d.get("equationOfState"), rho0))
    return float(rho0)*soundSpeedAtRest(case)


def _failureCause(rc, work):
    """What may have stopped a program of the column (adv54 v06 (c), n18,
    n36: under ulimit -f, ulimit -t or a full TMPDIR only the program's
    own IOstream error was quoted): its signal, and the limits and free
    space of the folder it wrote in; "" if none applies."""
    import resource
    import signal as sig
    notes = []
    if rc < 0:
        try:
            name = sig.Signals(-rc).name
        except ValueError:
            name = "signal %d" % -rc
        what = {"SIGXCPU": "the CPU time limit (ulimit -t)",
                "SIGXFSZ": "the file size limit (ulimit -f)",
                "SIGKILL": "killed: the CPU time limit's hard kill (ulimit "
                           "-t), out of memory, or another process"}
        notes.append("it ended by %s%s" % (name, ": " + what[name]
                                           if name in what else ""))
    for limit, text in ((resource.RLIMIT_FSIZE, "a file size limit of %d "
                         "bytes (ulimit -f)"),
                        (resource.RLIMIT_CPU, "a CPU time limit of %d s "
                         "(ulimit -t)")):
        soft = resource.getrlimit(limit)[0]
        if soft != resource.RLIM_INFINITY:
            notes.append(text % soft)
    try:
        st = os.statvfs(work)
        free = st.f_bavail*st.f_frsize
        if free < (64 << 20):
            notes.append("%d bytes free on the device of %s (TMPDIR: the "
                         "column is run there)" % (free, work))
    except OSError:
        pass
    return "; " + "; ".join(notes) if notes else ""


def estimatedSteps(case, endTime, dz, maxCo=0.5):
    """The time steps of the column of <case> to endTime [s] in cells of dz
    [m]: endTime/(maxCo dz/c), c the sound speed at rest (a lower bound: a
    pulse's state is faster)."""
    return endTime/(maxCo*dz/soundSpeedAtRest(case))


def columnControlDict(endTime, maxCo, probes, maxSteps):
    """The text of the 1D column's system/controlDict: its step limit is
    planeWave's -maxSteps (adv48b g49: -maxSteps 1e15 accepted, then the 1D
    run refused by its default maxSteps 1e8, an entry the user cannot
    set)."""
    return _CONTROL.format(end=endTime, co=maxCo, probes=probes,
                           steps="%.17g" % maxSteps)


def column(case, heights, Z, endTime, dz=25e-9, maxCo=0.5, work=None,
           maxCells=100000, scene=False, maxSteps=1e6, material=()):
    """Run the 1D column of <case> (water column of height Z [m]; the
    patches top and bottom) to endTime [s] with cells of dz [m], probes at
    heights [m]; returns a PlaneWave (p, rho and u at each height). With
    material (reference heights [m], the solid's probes): the histories
    at those material points as well (PlaneWave.material: the band of
    materialBand() probed around each, materialHistory()). The
    top and bottom conditions are the case's; for a planeWaveInflow top
    (a scene shorter than the column), the classic top instead: p
    uniformFixedValue with its pulse table, U and T zeroGradient, and Z
    must be its columnHeight. scene: keep a planeWaveInflow top as the
    case has it (with its constant/inflowWave): the 1D version of the
    scene's own shortened column, Z its inflow height (the boundary
    condition checks it against the file). work: the folder of the run (kept), else a
    temporary one. A column of more than maxCells cells, or of more than
    maxSteps time steps (estimatedSteps), is refused before anything is
    written (its cost is cells times steps; issue 19: -endTime 1 ran for
    about 6e10 steps, no output)."""
    if not (math.isfinite(Z) and Z > 0 and math.isfinite(dz) and dz > 0):
        raise PlaneWaveError("column height %g m and cell size %g m must "
                             "be positive and finite" % (Z, dz))
    if not (math.isfinite(endTime) and endTime > 0):
        raise PlaneWaveError("end time %g s must be positive and finite"
                             % endTime)
    if Z/dz > maxCells:
        raise PlaneWaveError(
            "a column of %g m in cells of %g m has %s cells, above the "
            "limit of %d (-maxCells raises it; the run's cost grows as the "
            "square of the cell count)"
            % (Z, dz, ranges.countAbove(Z/dz, maxCells), maxCells))
    steps = estimatedSteps(case, endTime, dz, maxCo)
    if not steps <= maxSteps:
        raise PlaneWaveError(
            "a column to %g s in cells of %g m takes about %s time steps "
            "(end time / (maxCo %g x dz / c), c = %g m/s the sound speed at "
            "rest), above the limit of %s (-maxSteps raises it; a shorter "
            "-endTime or a coarser -dz takes fewer)"
            % (endTime, dz, ranges.countAbove(steps, maxSteps), maxCo,
               soundSpeedAtRest(case), ranges.countText(maxSteps)))
    n = int(round(Z/dz))
    if n < 1 or abs(n*dz - Z) > 1e-9*Z:
        raise PlaneWaveError("dz %g m does not divide the column height "
                             "%g m" % (dz, Z))
    for z in list(heights) + list(material):
        if not 0 <= z <= Z:
            raise PlaneWaveError("probe height %g m outside the column "
                                 "[0, %g] m" % (z, Z))
    bands = {}
    if material:
        amp, T = pulseShape(appliedPressure(case))
        imp = impedanceAtRest(case)
        bands = {z: materialBand(z, amp, T, imp, dz, Z)
                 for z in sorted(set(material))}
    sampled = sorted(set(heights).union(*bands.values()))
    inflow = inflowColumnHeight(case) is not None and not scene
    if not scene:
        checkColumnHeight(case, Z)
    pulse = appliedPressure(case) if inflow else None
    keep = work is not None
    work = work or tempfile.mkdtemp(prefix="planeWave.")
    # SIGTERM, SIGHUP: rhoRiemannFoam ended and the scratch folder removed
    # on the way out (were left running and behind: adv28 z3)
    with signals.stopOn("planeWave"):
        try:
            if os.path.exists(work):
                shutil.rmtree(work)
            for d in ("0", "constant", "system"):
                os.makedirs(os.path.join(work, d))
            shutil.copy(os.path.join(case, "constant",
                                     "thermophysicalProperties"),
                        os.path.join(work, "constant"))
            # with the entries an Allrun's options put in <dict>.allrun,
            # which the dictionary includes (#sinclude: without the file
            # the column would run without them, e.g. -waterViscosity's
            # riemann { viscous true; mu MU; })
            for f in ("fvSchemes", "fvSolution"):
                for name in (f, f + ".allrun"):
                    src = os.path.join(case, "system", name)
                    if name == f or os.path.isfile(src):
                        shutil.copy(src, os.path.join(work, "system"))
            if scene and os.path.isfile(os.path.join(case, INFLOW_FILE)):
                shutil.copy(os.path.join(case, INFLOW_FILE),
                            os.path.join(work, "constant"))
            with open(os.path.join(work, "system", "blockMeshDict"), "w") as f:
                f.write(_BLOCK_MESH.format(w=dz, Z=Z, n=n))
            probes = " ".join("(%.17g %.17g %.17g)" % (0.5*dz, z, 0.5*dz)
                              for z in sampled)
            with open(os.path.join(work, "system", "controlDict"), "w") as f:
                f.write(columnControlDict(endTime, maxCo, probes, maxSteps))
            for field, cls in (("p", "volScalarField"),
                               ("T", "volScalarField"),
                               ("U", "volVectorField")):
                path = _fieldFile(case, field)
                if not inflow:
                    top = _patchEntry(path, "top")
                elif field == "p":
                    top = ("    top { type uniformFixedValue; uniformValue "
                           "table ( %s ); }" % " ".join(
                               "(%.17g %.17g)" % r for r in pulse))
                else:
                    top = "    top { type zeroGradient; }"
                with open(os.path.join(work, "0", field), "w") as f:
                    f.write(_FIELD.format(
                        cls=cls, name=field,
                        dims=_foamDictionary(path, "dimensions", True).strip(),
                        internal=_foamDictionary(path, "internalField",
                                                 True).strip(),
                        top=top,
                        bottom=_patchEntry(path, "bottom")))
            for app in ("blockMesh", "rhoRiemannFoam"):
                with open(os.path.join(work, "log." + app), "w") as out:
                    rc = signals.call([app, "-case", work], stdout=out,
                                      env=_foamEnv(),
                                      stderr=subprocess.STDOUT)
                if rc != 0:
                    # the scratch folder is kept for its log (issue 19, adv28
                    # pa16: the message named a log already removed), and the
                    # log's error quoted
                    keep = True
                    log = os.path.join(work, "log." + app)
                    raise PlaneWaveError("%s failed on the 1D column in %s "
                                         "(kept; its log.%s says: %s)%s"
                                         % (app, work, app, _logError(log),
                                            _failureCause(rc, work)))
            data = postProcessing.series(work, "probes/p")
            rho = postProcessing.series(work, "probes/rho")
            # the column's axis is y (_BLOCK_MESH): u is U's y component
            U = postProcessing.series(work, "probes/U", vectors=True)
            T = postProcessing.series(work, "probes/T")
            p, rho, U, T = data[:, 1:], rho[:, 1:], U[:, 2::3], T[:, 1:]
            col = [sampled.index(z) for z in heights]
            wave = PlaneWave(heights, data[:, 0], p[:, col], dz, Z,
                             rho[:, col], U[:, col], T[:, col])
            for z0, band in bands.items():
                b = [sampled.index(z) for z in band]
                wave.material[z0] = materialHistory(
                    wave.t, band, p[:, b], rho[:, b], U[:, b], z0, T[:, b])
            wave.thermoDigest = _recordedThermo(work)
            wave.inputDigests = _recordedDigests(work)
            return wave
        finally:
            if not keep:
                shutil.rmtree(work, ignore_errors=True)


THERMO = "constant/thermophysicalProperties"


def _lastRecord(work):
    """(time name, path) of the input record of the last time written in
    work that has one (<time>/uniform/inputDigests), else (None, None)"""
    times = []
    for name in os.listdir(work):
        try:
            times.append((float(name), name))
        except ValueError:
            pass
    for _, name in sorted(times, reverse=True):
        path = os.path.join(work, name, "uniform", "inputDigests")
        if os.path.isfile(path):
            return name, path
    return None, None


def _recordedDigests(work):
    """{input: digest} of the input record of the last time written in
    work ("<sha1>  <path>" lines: foamTools::inputRecord, the one digest
    of the project's input records); {} if there is none"""
    _, path = _lastRecord(work)
    record = {}
    if path:
        with open(path, errors="replace") as f:
            for line in f:
                digest, _, item = line.rstrip("\n").partition("  ")
                record[item] = digest
    return record


def _recordedThermo(work):
    """The digest of constant/thermophysicalProperties that rhoRiemannFoam
    recorded in the last time it wrote in work (<time>/uniform/
    inputDigests; planeWaveInflow compares the case's with it). None if
    there is none."""
    return _recordedDigests(work).get(THERMO)


#: The inputs of a case the 1D column is computed from (copied into it)
COLUMN_INPUTS = (THERMO, "system/fvSchemes", "system/fvSolution")


_CONDITION = re.compile(r"^(field |initial (?:boundary condition|conditions) "
                        r"(?:processor\d+/)?[^/]+/)(p|U|T), "
                        r"boundaryField/(top|bottom)$")


def _conditions(record):
    """{(kind, field, patch): digest} of the top and bottom conditions of
    p, U and T in an input record, its keys "field p, boundaryField/top"
    (kind "field") and "initial boundary condition 0/p, boundaryField/top"
    (kind "initial", whatever the start directory: the condition as its
    patch field writes it, the same from 0/p and from decomposePar's
    processor0/0/p, adv38 x73). A record of an earlier build holds
    "initial conditions 0/p, ..." instead, a digest of the entry's text
    (kind "initialText": compared only with its own kind)"""
    found = {}
    for key, digest in record.items():
        m = _CONDITION.match(key)
        if m:
            kind = "field" if key.startswith("field ") else \
                "initial" if key.startswith("initial boundary ") else \
                "initialText"
            found[(kind, m.group(2), m.group(3))] = digest
    return found


def checkRunInputs(case, wave):
    """Refuse (PlaneWaveError) to compare the run of case with a column
    computed from inputs that differ from those the run recorded (the
    last time of the case, or of its processor0, with a uniform/
    inputDigests): the 1D answer would be that of another water, other
    numerics or another pulse (adv37 w50: C0 changed after the run,
    compared without a word, errors 12.6 -> 35.6 %; w111: the next run's
    pulse set in 0/p, +70.7 %). The column's own record (rhoRiemannFoam's,
    the same digests) is compared with the run's: the files it copies
    (COLUMN_INPUTS) and, unless the case's top is a planeWaveInflow (the
    column then applies the pulse of constant/inflowWave, which the
    boundary condition checks), the top and bottom conditions of p, U and
    T it takes from 0/. Nothing to compare with when the run has no
    record (a run of an earlier build)."""
    column = getattr(wave, "inputDigests", None) or {}
    for where in (case, os.path.join(case, "processor0")):
        if not os.path.isdir(where):
            continue
        time, path = _lastRecord(where)
        if path is None:
            continue
        run = _recordedDigests(where)
        changed = [f for f in COLUMN_INPUTS
                   if f in run and f in column and run[f] != column[f]]
        if inflowColumnHeight(case) is None:
            now, was = _conditions(column), _conditions(run)
            for key in sorted(k for k in now if k in was
                              and now[k] != was[k]):
                name = "0/%s, boundaryField/%s" % key[1:]
                if name not in changed:
                    changed.append(name)
        if changed:
            raise PlaneWaveError(
                "%s changed since the run in %s (its inputs as recorded at "
                "t = %s s, %s): the 1D answer would be computed with other "
                "inputs than the run's and the comparison would be "
                "meaningless. Restore %s as the run had %s, or run the case "
                "again with the new %s"
                % (", ".join(changed), case, time,
                   os.path.relpath(path, case),
                   "it" if len(changed) == 1 else "them",
                   "it" if len(changed) == 1 else "them",
                   "input" if len(changed) == 1 else "inputs"))
        return


def _logError(path, lines=6):
    """The error lines of an application's log (from its first FATAL or
    error line, at most lines of them; else its last lines), on one line."""
    try:
        with open(path, errors="replace") as f:
            text = [l.strip() for l in f if l.strip()]
    except OSError as e:
        return "(not readable: %s)" % e
    first = next((i for i, l in enumerate(text)
                  if "FATAL" in l or "rror" in l), None)
    part = text[first:first + lines] if first is not None \
        else text[-lines:]
    return " / ".join(part) if part else "(empty)"


def writeReference(path, wave, what):
    """Write a PlaneWave as a column file: time [s], then p_z<height>[Pa]
    per height, then rho_z<height>[kg/m^3] per height when the wave has
    densities, then T_z<height>[K] when it has temperatures as well (what:
    the description line); then per material point (PlaneWave.material,
    by its reference height) pM_z<height>[Pa], rhoM_z<height>[kg/m^3],
    TM_z<height>[K] (with temperatures) and zM_z<height>[m], its height.
    Its digests beside it (resultDigest.writeSidecar): readReference
    verifies them (adv52 p06b)."""
    cols = ["p_z%.17g[Pa]" % z for z in wave.heights]
    data = wave.p
    if wave.rho is not None:
        cols += ["rho_z%.17g[kg/m^3]" % z for z in wave.heights]
        data = np.hstack((wave.p, wave.rho))
        if wave.T is not None:
            cols += ["T_z%.17g[K]" % z for z in wave.heights]
            data = np.hstack((data, wave.T))
    for z0 in sorted(wave.material):
        m = wave.material[z0]
        for key, unit in (("p", "Pa"), ("rho", "kg/m^3"), ("T", "K"),
                          ("z", "m")):
            if m[key] is not None:
                cols.append("%sM_z%.17g[%s]" % (key, z0, unit))
                data = np.column_stack((data, m[key]))
    with script.writing(path) as f:
        f.write("# %s\n# time [s]  %s\n" % (what, " ".join(cols)))
        for k in range(len(wave.t)):
            f.write("%.10g %s\n" % (wave.t[k], " ".join(
                "%.12g" % v for v in data[k])))
    resultDigest.writeSidecar(path)


def readMeasures(path):
    """The rows of planeWave's measures.dat or solidMeasures.dat (the
    utility's output, postProcessing/planeWave/<start>/): a list of dicts
    by the column names of the last comment line before the data, units
    dropped ('peak1ns[MPa]' -> 'peak1ns'), in the file's column order;
    numbers as floats, words (probe names, regions) as they are. The file
    must be as planeWave wrote it (its digests, written beside it since
    fix19k: resultDigest.check; a file of an earlier planeWave needs the
    script's option for hand-made files)."""
    resultDigest.uncoveredRows(path, resultDigest.check(path), partial=False)
    names, rows = None, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                if rows:
                    raise PlaneWaveError("%s: a comment line after its data "
                                         "rows: not a planeWave measures "
                                         "file" % path)
                names = re.sub(r"\[[^\]]*\]", "", line[1:]).split()
                continue
            w = line.split()
            if not w:
                continue
            if names is None or len(w) != len(names):
                raise PlaneWaveError(
                    "%s: a row of %d words under a header of %s: not a "
                    "planeWave measures file" % (path, len(w),
                                                 len(names or [])))
            row = {}
            for k, x in zip(names, w):
                try:
                    row[k] = float(x)
                except ValueError:
                    row[k] = x
            rows.append(row)
    return rows


def readReference(path):
    """The PlaneWave of a file of writeReference (densities and
    temperatures if it has them). The file must be as writeReference
    wrote it (its digests, resultDigest.check; adv52 p06b: reference.dat
    x1.5 was measured against), unless the script's option accepts a
    hand-made one."""
    # written whole: a row after its digests was appended (adv54 n02 (b))
    resultDigest.uncoveredRows(path, resultDigest.check(path), partial=False)
    table = postProcessing.readTable(path)
    # a reference is a finished file: a last row cut (fewer columns than
    # the header's, or no end of line) is refused, not dropped (adv51 n07:
    # the reference then ended before the later probes' arrivals, "not
    # compared", exit 0)
    if table.cut is not None:
        raise PlaneWaveError("%s, line %d: the last row is cut (fewer "
                             "columns than the others, or no end of line):"
                             " the file is cut or damaged; write the "
                             "reference again (planeWave)"
                             % (path, table.cut))
    d = table.data()
    names = table.names[1:]
    # the material points' columns (after the heights' ones)
    kinds = [re.match(r"(p|rho|T|z)M_z(.+)$", n) for n in names]
    first = next((i for i, m in enumerate(kinds) if m), len(names))
    material = {}
    for i, m in enumerate(kinds[first:], first):
        try:
            z0 = float(m.group(2)) if m else None
        except ValueError:
            z0 = None
        if z0 is None or m.group(1) in material.get(z0, {}):
            raise PlaneWaveError("%s: column %s among the material points' "
                                 "columns is not pM_z, rhoM_z, TM_z or "
                                 "zM_z<height>" % (path, names[i]))
        material.setdefault(z0, {})[m.group(1)] = d[:, 1 + i]
    for z0, m in material.items():
        if not {"p", "rho"} <= set(m):
            raise PlaneWaveError("%s: the material point of height %g m has "
                                 "columns %s, not pM_z and rhoM_z"
                                 % (path, z0, sorted(m)))
        m.setdefault("T", None)
        m.setdefault("z", None)
    names = names[:first]
    d = d[:, :1 + first]
    nP = sum(1 for n in names if n.startswith("p_z"))
    nT = sum(1 for n in names if n.startswith("T_z"))
    try:
        heights = [float(n[3:]) for n in names[:nP]]
        rhoHeights = [float(n[5:]) for n in names[nP:2*nP]]
        THeights = [float(n[3:]) for n in names[2*nP:]]
    except ValueError:
        raise PlaneWaveError("%s: columns %s are not p_z<height> "
                             "[rho_z<height> [T_z<height>]]" % (path, names))
    if nP == 0 or (rhoHeights and rhoHeights != heights) \
            or (THeights and THeights != heights) \
            or len(names) not in (nP, 2*nP, 3*nP) or nT != len(THeights):
        raise PlaneWaveError("%s: columns %s are not p_z<height> "
                             "[rho_z<height> [T_z<height>]]" % (path, names))
    # a reference is a history: at least two rows, every value finite
    # (adv51 m06: a header-only file ended in an IndexError, a nan row was
    # printed as a reference value, "50.00/nan (+nan %)")
    if d.ndim != 2 or len(d) < 2:
        raise PlaneWaveError("%s: %d row%s of values: a reference is a "
                             "history of at least 2 rows (written by "
                             "planeWave; the file is cut or damaged)"
                             % (path, len(d), "" if len(d) == 1 else "s"))
    bad = np.argwhere(~np.isfinite(d))
    if len(bad):
        r, c = bad[0]
        raise PlaneWaveError("%s: row %d, column %s is %s, not a finite "
                             "number: the file is damaged"
                             % (path, r + 1, table.names[c], d[r, c]))
    wave = PlaneWave(heights, d[:, 0], d[:, 1:1 + nP], None, None,
                     d[:, 1 + nP:1 + 2*nP] if rhoHeights else None,
                     T=d[:, 1 + 2*nP:] if THeights else None)
    wave.material = material
    return wave


_INFLOW_HEADER = """FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      inflowWave;
}
// The incident wave of a planeWaveInflow boundary: the 1D plane wave of the
// full water column (the pulse applied on its top face at columnHeight, the
// rigid substrate at z = 0; rhoRiemannFoam, neuronFsi.planeWave.column)
// sampled at the plane z = height, the scene's top.
%s

height          %.17g;  // [m] the plane's height above the substrate (the scene's top)
columnHeight    %.17g;  // [m] the physical column: the pulse is applied at its top face
pulse           table ( %s );  // [s Pa] gauge pressure applied there
dz              %.17g;  // [m] 1D cell size
// The water the wave was computed with: the column at rest at height, and
// the digest of its constant/thermophysicalProperties as rhoRiemannFoam
// recorded it (uniform/inputDigests). planeWaveInflow refuses a case
// whose water differs (its ambient state or its thermophysicalProperties)
ambientPressure %.17g;  // [Pa]
ambientTemperature %.17g;  // [K]
thermoDigest    "%s";
rowsDigest      "%s";  // SHA-1 of the rows below (each "%%.17g %%.17g %%.17g" and a newline): planeWaveInflow refuses rows changed since

// time [s], p [Pa, gauge], u [m/s]: velocity along the column axis,
// positive upwards (away from the substrate), at height
data
(
"""


def _dataLines(text):
    """The lines of a file's text that are not comments (// ...) or blank:
    what a reader of the file sees (comments record who wrote it)"""
    return [line.rstrip() for line in text.split("\n")
            if line.strip() and not line.lstrip().startswith("//")]


def writeInflow(path, wave, height, pulse, what, overwrite=False):
    """Write constant/inflowWave: p and u of the PlaneWave at one of its
    heights [m], with the column's height, the pulse table [(t [s],
    p [Pa])] and the 1D cell size, 17 significant digits (what: comment
    lines, e.g. the command that wrote it). The column's probes
    start at its first step; the first row is t = 0 with that step's
    values, the state at rest: the pulse needs (Z - height)/C0 to come
    down, and a uniform state is kept exactly by the scheme. Written to a
    temporary file first: an earlier file is replaced only by a complete
    one. An earlier file whose entries differ from the new ones (results
    may have been computed with it, or it holds an edit) is replaced only
    with overwrite; else a PlaneWaveError naming the first differing line,
    nothing written (issue 19: replaced without a word). One that differs
    in its comments only is replaced."""
    if wave.u is None:
        raise PlaneWaveError("the wave has no velocities: compute the "
                             "column")
    if wave.T is None or not getattr(wave, "thermoDigest", None):
        raise PlaneWaveError("the wave has no record of the water it was "
                             "computed with (temperatures and the digest "
                             "of its thermophysicalProperties): compute the "
                             "column")
    t, p, u = wave.t, wave.at(height), wave.velocityAt(height)
    # the column at rest at height: its first sample (the pulse has not
    # come down yet; a uniform state is kept exactly by the scheme)
    ambient = (float(p[0]), float(wave.temperatureAt(height)[0]))
    if t[0] > 0:
        t = np.concatenate(([0.0], t))
        p = np.concatenate((p[:1], p))
        u = np.concatenate((u[:1], u))
    rows = list(zip(t, p, u))
    text = [_INFLOW_HEADER % (
        "\n".join("// " + " ".join(line.split())
                  for line in what.split("\n")), height, wave.Z,
        " ".join("(%.17g %.17g)" % (a, b) for a, b in pulse), wave.dz,
        ambient[0], ambient[1], wave.thermoDigest, inflowDigest(rows))]
    # each number as OpenFOAM reads it (a denormal ahead of the wave as 0:
    # a dictionary's number up to 1e-300 is refused since fix19i)
    text += ["    (%.17g %.17g %.17g)\n" % tuple(_asRead(x) for x in r)
             for r in rows]
    text.append(");\n")
    if not overwrite and os.path.exists(path):
        try:
            with open(path) as f:
                old = _dataLines(f.read())
        except (OSError, UnicodeDecodeError) as err:
            raise PlaneWaveError("%s exists and cannot be read (%s): "
                                 "-overwrite replaces it" % (path, err))
        new = _dataLines("".join(text))
        if old != new:
            k = next((i for i, (a, b) in enumerate(zip(old, new)) if a != b),
                     min(len(old), len(new)))
            raise PlaneWaveError(
                "%s exists and differs from the wave computed now (line %d "
                "of its entries: %s in the file, %s now; %d and %d lines): "
                "results may have been computed with it, or it holds an "
                "edit. Give -overwrite to replace it (or remove it); nothing "
                "was written"
                % (path, k + 1,
                   repr(old[k][:80]) if k < len(old) else "the end",
                   repr(new[k][:80]) if k < len(new) else "the end",
                   len(old), len(new)))
    with script.replacing(path) as f:
        f.write("".join(text))


def inflowDigest(rows):
    """The SHA-1 (hex) of the data rows [(t, p, u)] of a
    constant/inflowWave, each written "%.17g %.17g %.17g\\n" as OpenFOAM
    reads it (_asRead; C's printf
    and Python's % give the same digits): the entry rowsDigest, which the
    planeWaveInflow boundary compares with the rows it reads."""
    return hashlib.sha1("".join(
        "%.17g %.17g %.17g\n" % tuple(_asRead(x) for x in r)
        for r in rows).encode()).hexdigest()


def _asRead(x):
    """x as OpenFOAM reads it back from %.17g: a magnitude up to 1e-300
    (OpenFOAM's VSMALL: it rounds such numbers to zero, e.g. 7.4e-308 m/s
    in the rest ahead of a wave) as 0, -0.0 as 0 ("-0" is read as the
    integer 0)."""
    x = float(x)
    return 0.0 if abs(x) <= 1e-300 else x


def readInflow(path):
    """The entries of a constant/inflowWave file (writeInflow): a dict
    with height, columnHeight, dz [m], pulse [(t [s], p [Pa])] and the
    arrays t [s], p [Pa], u [m/s]; a PlaneWaveError naming the file and
    the entry when one is missing or wrong."""
    try:
        d = foamDict.read(path)
    except (OSError, foamDict.DictError) as err:
        raise PlaneWaveError("%s: %s" % (path, err))
    out = {}
    for key in ("height", "columnHeight", "dz"):
        v = d.get(key)
        if isinstance(v, bool) or not isinstance(v, (int, float)) \
                or not (math.isfinite(v) and v > 0):
            raise PlaneWaveError("%s: entry '%s' = %s: must be a length "
                                 "[m], positive and finite" % (path, key, v))
        out[key] = float(v)
    if "pulse" not in d:
        raise PlaneWaveError("%s: no entry 'pulse'" % path)
    out["pulse"] = _table(path, "entry 'pulse'", d["pulse"])
    try:
        data = np.array(d["data"], dtype=float)
    except KeyError:
        raise PlaneWaveError("%s: no entry 'data'" % path)
    except (TypeError, ValueError):
        raise PlaneWaveError("%s: entry 'data' is not a list of (t p u) "
                             "rows of numbers" % path)
    if data.ndim != 2 or data.shape[1] != 3 or len(data) < 2 \
            or not np.isfinite(data).all():
        raise PlaneWaveError("%s: entry 'data' is not a list of two or "
                             "more (t p u) rows of finite numbers" % path)
    if not (np.diff(data[:, 0]) > 0).all():
        k = int(np.argmin(np.diff(data[:, 0]) > 0))
        raise PlaneWaveError("%s: entry 'data': row %d at time %g s is not "
                             "after row %d at %g s" % (
                                 path, k + 2, data[k + 1, 0], k + 1,
                                 data[k, 0]))
    out["t"], out["p"], out["u"] = data[:, 0], data[:, 1], data[:, 2]
    # the water it was computed with (files written since issue 19)
    for key in ("ambientPressure", "ambientTemperature", "thermoDigest"):
        if key in d:
            out[key] = d[key]
    # the rows as written: their digest is required, as by the boundary
    # (adv29 w09c, w09e: a wave without it ran unchecked)
    if "rowsDigest" not in d:
        raise PlaneWaveError("%s: no entry 'rowsDigest': its data rows "
                             "cannot be checked against what planeWave "
                             "-inflow wrote. Compute it again: planeWave "
                             "-inflow %g -overwrite" % (path, out["height"]))
    if inflowDigest(data) != d["rowsDigest"]:
        raise PlaneWaveError("%s: entry 'data': the rows are not those "
                             "planeWave -inflow wrote (their SHA-1 is %s, "
                             "the entry rowsDigest %s): compute it again "
                             "(planeWave -inflow %g -overwrite), do not edit "
                             "it" % (path, inflowDigest(data),
                                     d["rowsDigest"], out["height"]))
    try:
        foamDict.check_keywords(d, INFLOW_KEYWORDS, path)
    except foamDict.DictError as err:
        raise PlaneWaveError(str(err))
    return out


def setInflowBoundary(case, columnHeight, inflowFile=INFLOW_FILE):
    """Make the top of <case>/0/p, U and T a planeWaveInflow boundary: p
    with columnHeight [m], the pulse table of 0/p's top (its uniformValue
    table, or the pulse of an inflow top already there) and the file of
    the incident wave; every field's value the internal field's (uniform).
    Edits 0/ only (restored from 0.orig by restore0Dir), never 0.orig."""
    if not (math.isfinite(columnHeight) and columnHeight > 0):
        raise PlaneWaveError("column height %g m must be positive and "
                             "finite" % columnHeight)
    files = {f: os.path.join(case, "0", f) for f in ("p", "U", "T")}
    for f, path in files.items():
        if not os.path.isfile(path):
            raise PlaneWaveError("%s: no such file (the top is set in 0/, "
                                 "restored from 0.orig first)" % path)
    pulse = appliedPressure(case)
    texts = {}
    for f, path in files.items():
        with open(path) as src:
            text = src.read()
        try:
            internal = foamDict.parse(text, path)["internalField"]
        except KeyError:
            raise PlaneWaveError("%s: no internalField" % path)
        except foamDict.DictError as err:
            raise PlaneWaveError(str(err))
        if not (isinstance(internal, list) and len(internal) == 2
                and internal[0] == "uniform"):
            raise PlaneWaveError("%s: internalField is not uniform: the "
                                 "top's value is the internal field's"
                                 % path)
        entries = {"type": INFLOW}
        if f == "p":
            entries["columnHeight"] = "%.17g" % columnHeight
            entries["pulse"] = "table ( %s )" % " ".join(
                "(%.17g %.17g)" % r for r in pulse)
            entries["file"] = '"%s"' % inflowFile
        entries["value"] = "uniform " + foamDict.format_value(internal[1])
        texts[path] = foamDict.set_subdict(
            text, ["boundaryField", "top"], entries, path,
            {"columnHeight": "m", "pulse": "s Pa"})
    for path, text in texts.items():          # all three read, then written
        with script.writing(path) as out:
            out.write(text)


def isWedge(case):
    """True when the fluid mesh is an r-z wedge (height along y, the solid
    probes' points (r z 0)); else 3D (height along z)."""
    path = os.path.join(case, "constant", "polyMesh", "boundary")
    if not os.path.isfile(path):
        return False
    with open(path) as f:
        return "wedge" in f.read()


def caseProbes(case, solid=True, fluid=True):
    """[(name, height [m], t [s], p [Pa])] of a blast case's probes: the
    solid probes (postProcessing/solidProbes, pressure p<i> at the probe's
    reference point) and every OpenFOAM probes function object sampling
    p (postProcessing/<name>/<start>/p)."""
    axis = 1 if isWedge(case) else 2
    out = []
    notFound = set()        # fluid probes OpenFOAM reports outside the mesh
    log = "solidProbes/solidProbes.dat"
    if solid and _has(case, log):
        data = postProcessing.series(case, log, verify=True)
        # a cut file is not the run (adv34 n14)
        postProcessing.checkCovers(case, log, data)
        cols = postProcessing.names(case, log)
        out += [("solid p%d" % i, q["point"][axis], data[:, 0],
                 data[:, cols.index("p%d" % i)])
                for i, q in enumerate(postProcessing.probes(case, log))]
    for d in sorted(glob.glob(os.path.join(case, "postProcessing", "*"))):
        log = os.path.basename(d) + "/p"
        if not fluid or not _has(case, log):
            continue
        data = None
        for line in postProcessing.header(case, log):
            m = re.match(r"Probe (\d+) \((\S+) (\S+) (\S+)\)", line)
            if m:
                if data is None:
                    data = postProcessing.series(case, log, verify=True)
                    # OpenFOAM's probes follow the step they sample: one
                    # step short of the latest time written is whole
                    # (adv34 n14: a file cut at 2/3, impulse -11 %, exit 0)
                    postProcessing.checkCovers(case, log, data,
                                               afterStep=True)
                i = int(m.group(1))
                if "Not Found" in line:
                    notFound.add("%s %d" % (os.path.basename(d), i))
                out.append(("%s %d" % (os.path.basename(d), i),
                            float(m.group(2 + axis)), data[:, 0],
                            data[:, 1 + i]))
    # probes above the mesh's water (a shortened scene's column above its
    # inflow top, a probe set for a taller column): outside the mesh, not
    # measured (the caller leaves out the probes above its column)
    top = meshTop(case)
    for name, z, t, p in out:
        if top is not None and z > top*(1 + 1e-9):
            continue
        # a probe history with a nan or inf is no history to measure
        # (adv34 n14: nan errors printed, exit 0)
        bad = np.flatnonzero(~np.isfinite(p))
        if len(bad):
            raise PlaneWaveError(
                "probe '%s' of %s: its pressure at t = %.10g s is %s (row "
                "%d of its history in postProcessing): the file is damaged "
                "or the run failed; nothing compared"
                % (name, case, t[bad[0]], p[bad[0]], bad[0] + 1))
        # OpenFOAM's fill for a probe outside the mesh (adv35 t42: read as
        # a peak of -1e+294 MPa, exit 0)
        bad = np.flatnonzero(np.abs(p) >= OUT_OF_MESH)
        if name in notFound and not len(bad):
            bad = [0]
        if len(bad):
            raise PlaneWaveError(
                "probe '%s' of %s at height %g m: its pressure at t = %.10g "
                "s is %g Pa (row %d of postProcessing/%s): OpenFOAM found no "
                "cell holding its location ('Not Found' in the header, "
                "-1e+300 its fill for such a probe): "
                "move the probe into the water (the mesh's water ends at "
                "%s) or leave it out (-probes); nothing compared"
                % (name, case, z, t[bad[0]], p[bad[0]], bad[0] + 1,
                   "solidProbes/solidProbes.dat" if name.startswith("solid ")
                   else name.split(" ")[0] + "/<start>/p",
                   "an unknown height" if top is None else "%g m" % top))
    return out


def _has(case, log):
    """True when the case has the log postProcessing/<dir>/<start>/<file>."""
    try:
        postProcessing.segments(case, log)
        return True
    except postProcessing.ColumnFileError:
        return False


def _crossing(t, p, level):
    """First time p reaches level (linear between samples); None if never."""
    above = np.nonzero(p >= level)[0]
    if not len(above):
        return None
    k = above[0]
    if k == 0:
        return t[0]
    return t[k - 1] + (level - p[k - 1])*(t[k] - t[k - 1])/(p[k] - p[k - 1])


def crossingAfter(t, p, t0, level):
    """The first time at or after t0 [s] at which p reaches level [Pa],
    linear between samples (from t0 itself if the sample before t0 is
    already at the level's side below); None if it never does. The echo's
    foot or arrival at a probe: crossingAfter(t, p, ta + 2 ns, 51e6)
    (bench/blast/analysis/incidentWindow.py, bench/blast/echoChain.py)."""
    t = np.asarray(t, dtype=float)
    p = np.asarray(p, dtype=float)
    k = np.flatnonzero((t >= t0) & (p >= level))
    if not len(k):
        return None
    k = k[0]
    if k == 0 or t[k - 1] < t0:
        return t[k]
    return t[k - 1] + (level - p[k - 1])*(t[k] - t[k - 1])/(p[k] - p[k - 1])


def arrival(t, p, amplitude):
    """The arrival of a pulse of amplitude [Pa] in p(t): the first time p
    reaches half of it [s]; None if it never does."""
    return _crossing(np.asarray(t), np.asarray(p), 0.5*amplitude)


def _integral(t, p, a, b):
    """int_a^b p dt, trapezoidal on the samples, p linear between them."""
    if b <= a:
        return 0.0
    tt = np.concatenate(([a], t[(t > a) & (t < b)], [b]))
    return np.trapz(np.interp(tt, t, p), tt)


def runningMean(t, p, window):
    """The mean of p over [t - window/2, t + window/2] at every sample
    whose window lies inside the data (exact for p linear between
    samples)."""
    P = np.concatenate(([0.0], np.cumsum(0.5*(p[1:] + p[:-1])*np.diff(t))))
    ok = (t - 0.5*window >= t[0]) & (t + 0.5*window <= t[-1])
    tc = t[ok]

    def prim(x):
        k = np.clip(np.searchsorted(t, x) - 1, 0, len(t) - 2)
        dt = x - t[k]
        slope = (p[k + 1] - p[k])/(t[k + 1] - t[k])
        return P[k] + p[k]*dt + 0.5*slope*dt*dt

    return tc, (prim(tc + 0.5*window) - prim(tc - 0.5*window))/window


def measures(t, p, tRef, pRef, amplitude, duration, z, c0=1450.0):
    """The issue-17 numbers of a history p(t) (see the module text) and
    of the reference pRef(tRef) at the same height z [m]; the windows are
    taken from the reference. Returns (scene, reference) dicts."""
    t = np.asarray(t, dtype=float)
    p = np.asarray(p, dtype=float)
    ta = arrival(tRef, pRef, amplitude)
    if ta is None:
        raise PlaneWaveError("the reference never reaches half the applied "
                             "pressure at z = %g m" % z)
    # the echo's return: on the early side for the incident windows (it
    # travels up through the compressed, moving water of the incident
    # pulse: about 1531 m/s for 50 MPa in water, faster at 100 MPa; 10 %
    # above c0), on the late side (c0) for the end of the passage
    echo = 2*z/(1.1*c0)
    plateau = (ta + 1e-9, ta + min(duration, echo) - 1e-9)
    passage = (ta - 2e-9, ta + duration + 2*z/c0 + 5e-9)
    incident = (ta, ta + min(duration, echo) - 0.5e-9)
    # both over the span both cover: the scene's logs may end before the
    # reference (a run cut, or the 1D column's step past the end time),
    # and a window cut in one only compared two different quantities
    # (adv49b i43: impulse -17.6 % of a run killed at 3.38 ns; a finished
    # run's -5.6 % from the reference's extra step)
    start, end = max(t[0], tRef[0]), min(t[-1], tRef[-1])
    a, b = max(passage[0], start), min(passage[1], end)
    out = []
    for tt, pp in ((t, p), (tRef, pRef)):
        tc, mean = runningMean(tt, pp, 1e-9)
        inSpan = (tc - 0.5e-9 >= start) & (tc + 0.5e-9 <= end)
        mean, tc = mean[inSpan], tc[inSpan]
        inc = mean[(tc >= incident[0]) & (tc <= incident[1])]
        out.append({
            "arrival": _crossing(tt, pp, 0.5*amplitude),
            "peak1ns": mean.max() if len(mean) else None,
            "peakIncident": inc.max() if len(inc) else None,
            "plateau": (_integral(tt, pp, *plateau)
                        /(plateau[1] - plateau[0])
                        if plateau[1] - plateau[0] >= 1e-9
                        and plateau[1] <= end else None),
            "impulse": _integral(tt, pp, a, b),
            "impulseWindow": (a, b),
        })
    return out[0], out[1]


REST = 140e-9   # [s] "after the pulse" of the 100 um scene (issue 17 item 6)


def solidMaterial(case, region):
    """(rho0 [kg/m^3], mu0 = 2 C10 [Pa], [(mu_k [Pa], tau_k [s])]) of a
    region of <case>/constant/solidProperties (its materials expanded by
    foamDictionary -expand: the #include of the parameter set and the
    case's overrides)."""
    path = os.path.join(case, "constant", "solidProperties")
    out = subprocess.run(["foamDictionary", "-expand", path],
                         capture_output=True, text=True, env=_foamEnv())
    if out.returncode != 0:
        raise PlaneWaveError("%s: foamDictionary -expand failed (%s)"
                             % (path, out.stderr.strip()))
    d = foamDict.parse(out.stdout, path)
    try:
        m = d["materials"][region]
        rho0 = float(m.get("rho0", 1000))
        mu0 = 2*float(m["C10"])
        branches, k = [], 1
        while "mu%d" % k in m:
            mu = float(m["mu%d" % k])
            tau = (float(m["tau%d" % k]) if "tau%d" % k in m
                   else float(m["eta%d" % k])/mu)
            branches.append((mu, tau))
            k += 1
    except (KeyError, TypeError, ValueError) as err:
        raise PlaneWaveError("%s: materials/%s: %s" % (path, region, err))
    return rho0, mu0, branches


def solidMeasures(t, vm, ez, tRef, vmRef, ezRef, rest=REST):
    """Scene and reference measures of a solid probe's von Mises vm(t)
    [Pa] and longitudinal strain ez(t) [-]: the largest 1-ns running mean
    of von Mises, the most negative 1-ns mean of the strain (compression
    along the wave), and after the pulse (t >= rest) the largest |strain|
    and von Mises (None when the data end before rest + 5 ns). Returns
    (scene, reference) dicts."""
    out = []
    for tt, v, e in ((t, vm, ez), (tRef, vmRef, ezRef)):
        tt, v, e = (np.asarray(x, dtype=float) for x in (tt, v, e))
        _, mv = runningMean(tt, v, 1e-9)
        _, me = runningMean(tt, e, 1e-9)
        late = tt >= rest
        has = tt[-1] >= rest + 5e-9
        out.append({
            "vonMises1ns": mv.max() if len(mv) else None,
            "strain1ns": me.min() if len(me) else None,
            "restStrain": np.abs(e[late]).max() if has else None,
            "restVonMises": v[late].max() if has else None,
        })
    return out[0], out[1]


def errors(scene, ref):
    """Arrival difference [s] and relative errors [-] of peak1ns,
    peakIncident, plateau and impulse (None where either is missing)."""
    e = {"arrival": (None if scene["arrival"] is None
                     else scene["arrival"] - ref["arrival"])}
    for k in ("peak1ns", "peakIncident", "plateau", "impulse"):
        # a zero reference (the wave has not arrived): no relative error
        e[k] = (None if scene[k] is None or not ref[k]
                else scene[k]/ref[k] - 1)
    return e
