"""The uncertainty of the pulse study's indicators from that of the cell's
material parameters (issue 20 item 3; docs/userGuide/pulseStudy.md,
docs/results/uncertainty.md): the optional sub-dictionary 'uncertainty' of
system/pulseStudyDict, the runs it adds to the study, and the propagation.

    uncertainty
    {
        pulses      ((50e6 5e-9));  // (overpressure [Pa] duration [s]),
                                    // points of the study's grid
        variants                    // each one run per pulse
        {
            table       { materials table; }    // a set of etc/caseDicts/
                                                // cellMaterials
            calibrated  { materials table;      // then entries
                          cytoplasm.C10 0.1788 [Pa]; }
        }
        about       calibrated;     // base (the grid's run) or a variant:
                                    // the derivatives are taken there
        parameters
        {
            cytoplasm.C10 { interval (0.131 0.245) [Pa]; log yes; }
        }
        correlation ((cytoplasm.C10 nucleus.C10 -0.60)); // else independent
        difference  central;        // central | forward
        step        0.2;            // [-] in ln p (log yes) or p/|p0|
        checkStep   0.1;            // [-] the same with a second step
    }

A variant is a material change of the base case, run as a point of its
own: 'materials <set>' takes the deviatoric parameters (C10, mu<N>,
tau<N>) of every region of etc/caseDicts/cellMaterials/<set> (the base
case's volumetric laws are kept), then '<region>.<entry> value [unit]'
entries replace one parameter each. The change is written to
constant/solidProperties.pulseStudy of the point's copy, which its
solidProperties includes at its end (OpenFOAM's merge: the region's other
entries stay).

Linearisation. For parameter i with the 95 % interval [lo_i, hi_i] of the
calibration, the fitted variable x_i = ln p_i (log yes) or p_i (log no),
its half-width w_i = (ln hi_i - ln lo_i)/2 or (hi_i - lo_i)/2. About the
run 'about' (parameters p0_i), each indicator I is run at x_i + d_i and
(central) x_i - d_i, d_i = step (log) or step |p0_i| (log no):

    g_i = (I(x + d_i e_i) - I(x - d_i e_i))/(2 d_i)   (central)
    g_i = (I(x + d_i e_i) - I(x))/d_i                  (forward)
    c_i = g_i w_i                  the interval's half-width from i alone
    H   = sqrt(sum_ij c_i c_j R_ij)     R: the correlation matrix

and the indicator's 95 % interval is I(about) +- H. For an indicator
linear in the x_i and intervals all of the same quantile (q se_i) this
is exact: H = q sqrt(g^T C g), C = D R D the covariance, D = diag(se_i).
checkStep repeats it with a second step: the two H's differ by the
indicator's curvature (or noise) over the step.
"""

import math
import os
import re

import numpy as np

from . import foamDict, ranges

KEYWORDS = ("pulses", "variants", "about", "parameters", "correlation",
            "difference", "step", "checkStep")
PARAMETER_KEYWORDS = ("interval", "log")
# the unit of each material entry a variant or a parameter may change
ENTRY_UNITS = {"C10": "Pa", "rho0": "kg/m^3", "d0": "1/Pa", "C0": "m/s",
               "s": "-", "Gamma0": "-", "Cv": "J/kg/K", "T0": "K"}
_BRANCH = re.compile(r"(mu|tau)([1-9][0-9]*)\Z")
_UNIT = re.compile(r"\[(.*)\]\Z")
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")
MATERIAL_SETS = "etc/caseDicts/cellMaterials"


class UncertaintyError(Exception):
    pass


def entryUnit(entry):
    """The SI unit of a material entry, None if it is none of the known
    parameters."""
    m = _BRANCH.match(entry)
    if m:
        return "Pa" if m.group(1) == "mu" else "s"
    return ENTRY_UNITS.get(entry)


def baseMaterials(base):
    """{region: {entry: value}} of the base case's constant/
    solidProperties (its includes merged)."""
    path = os.path.join(base, "constant", "solidProperties")
    try:
        mats = foamDict.read(path).get("materials")
    except foamDict.DictError as err:
        raise UncertaintyError(str(err))
    if not isinstance(mats, dict):
        raise UncertaintyError("%s: no sub-dictionary 'materials'" % path)
    return {r: dict(v) for r, v in mats.items() if isinstance(v, dict)}


def _parameterName(name, mats, where):
    """(region, entry) of '<region>.<entry>', checked against the base
    case's materials."""
    parts = name.split(".") if isinstance(name, str) else []
    if len(parts) != 2:
        raise UncertaintyError("%s: '%s' is not <region>.<entry> (e.g. "
                               "cytoplasm.C10)" % (where, name))
    region, entry = parts
    if region not in mats:
        raise UncertaintyError(
            "%s: '%s': no region '%s' in the base case's materials%s "
            "(regions: %s)" % (where, name, region,
                               foamDict.did_you_mean(region, list(mats)),
                               " ".join(mats)))
    valid = [e for e in mats[region] if entryUnit(e)]
    if entry not in valid:
        raise UncertaintyError(
            "%s: '%s': region %s has no parameter '%s'%s (valid: %s)"
            % (where, name, region, entry,
               foamDict.did_you_mean(entry, valid), " ".join(valid)))
    return region, entry


def _withUnit(v, unit, where, form):
    """The number of 'v [unit]' (v a number or a list of numbers), unit
    checked."""
    if not isinstance(v, list) or len(v) != 2 or not isinstance(v[1], str) \
            or not _UNIT.match(v[1]):
        raise UncertaintyError("%s: %s has no unit: give it as '%s'"
                               % (where, foamDict.format_value(v), form))
    x, u = v
    if _UNIT.match(u).group(1) != unit:
        raise UncertaintyError("%s: %s %s: the unit of this entry is [%s] "
                               "(SI)" % (where, foamDict.format_value(x), u,
                                         unit))
    xs = x if isinstance(x, list) else [x]
    for y in xs:
        if isinstance(y, bool) or not isinstance(y, (int, float)) \
                or not math.isfinite(y):
            raise UncertaintyError("%s: '%s' is not a number: '%s'"
                                   % (where, foamDict.format_value(y), form))
    return [float(y) for y in xs] if isinstance(x, list) else float(x)


def materialSet(name, project, where):
    """{region: {entry: value}} of the deviatoric parameters (C10, mu<N>,
    tau<N>) of etc/caseDicts/cellMaterials/<name>."""
    folder = os.path.join(project, MATERIAL_SETS)
    path = os.path.join(folder, str(name))
    if not isinstance(name, str) or not _NAME.match(name) \
            or not os.path.isfile(path):
        sets = sorted(os.listdir(folder)) if os.path.isdir(folder) else []
        raise UncertaintyError("%s: materials '%s': no such set in %s%s "
                               "(sets: %s)" % (
                                   where, foamDict.format_value(name),
                                   folder, foamDict.did_you_mean(
                                       str(name), sets), " ".join(sets)))
    try:
        d = foamDict.read(path)
    except foamDict.DictError as err:
        raise UncertaintyError(str(err))
    return {r: {e: float(x) for e, x in v.items()
                if e == "C10" or _BRANCH.match(e)}
            for r, v in d.items() if isinstance(v, dict)}


def _variant(name, v, mats, project, where):
    w = "%s/%s" % (where, name)
    if not _NAME.match(name) or name == "base":
        raise UncertaintyError("%s: a variant's name is a word (letters, "
                               "digits, _; not 'base')" % w)
    if not isinstance(v, dict) or not v:
        raise UncertaintyError("%s: not a sub-dictionary { materials <set>;"
                               " <region>.<entry> <value> [<unit>]; }" % w)
    out = {}
    for key, x in v.items():
        if key == "materials":
            for r, e in materialSet(x, project, w).items():
                if r not in mats:
                    raise UncertaintyError(
                        "%s: materials %s: region '%s' is not a region of "
                        "the base case (%s)" % (w, x, r, " ".join(mats)))
                for k, y in e.items():
                    if k not in mats[r]:
                        raise UncertaintyError(
                            "%s: materials %s: %s.%s is not a parameter of "
                            "the base case's region" % (w, x, r, k))
                    out.setdefault(r, {})[k] = y
    for key, x in v.items():
        if key == "materials":
            continue
        region, entry = _parameterName(key, mats, w)
        unit = entryUnit(entry)
        out.setdefault(region, {})[entry] = _withUnit(
            x, unit, "%s: %s" % (w, key), "%s <number> [%s]" % (key, unit))
    return out


# The valid range of a finite-difference step (step, checkStep) [-], in ln p
# (log yes) or p/|p0|: a step of 1 moves a parameter by a factor e (log)
# or to 0 (central, linear), far from the linearisation; 1e3 overflowed
# e^step (adv48a h10: an OverflowError traceback)
STEP_RANGE = "(0, 1)"


def _step(d, key, where):
    v = d[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)) \
            or v not in ranges.Interval(STEP_RANGE):
        raise UncertaintyError("%s: entry '%s' = %s is outside the valid "
                               "range %s [-] (the finite difference's step "
                               "in ln p with log yes, else in p/|p0|)"
                               % (where, key, foamDict.format_value(v),
                                  STEP_RANGE))
    return float(v)


def read(d, where, base, grid, project):
    """The settings of the sub-dictionary d ('uncertainty' of the study's
    dictionary, named where) checked against the base case's materials
    and the grid ({'overpressure': [...], 'duration': [...]}); project:
    the project's folder (the material sets)."""
    w = "%s: uncertainty" % where
    if not isinstance(d, dict):
        raise UncertaintyError("%s: not a sub-dictionary" % w)
    try:
        foamDict.check_keywords(d, KEYWORDS, w)
    except foamDict.DictError as err:
        raise UncertaintyError(str(err))
    for k in ("pulses",):
        if k not in d:
            raise UncertaintyError("%s: no entry '%s'" % (w, k))
    if "variants" not in d and "parameters" not in d:
        raise UncertaintyError("%s: neither 'variants' nor 'parameters': "
                               "nothing to propagate" % w)
    mats = baseMaterials(base)
    s = {"base": mats}
    pulses = d["pulses"]
    if not isinstance(pulses, list) or not pulses:
        raise UncertaintyError("%s: entry 'pulses' is empty: give "
                               "((overpressure [Pa] duration [s]) ...), "
                               "points of the grid" % w)
    s["pulses"] = []
    for p in pulses:
        if not isinstance(p, list) or len(p) != 2 or not all(
                isinstance(x, (int, float)) and not isinstance(x, bool)
                for x in p):
            raise UncertaintyError("%s: entry 'pulses': %s is not "
                                   "(overpressure [Pa] duration [s])"
                                   % (w, foamDict.format_value(p)))
        A, T = float(p[0]), float(p[1])
        if A not in grid["overpressure"] or T not in grid["duration"]:
            # the digits that tell the values apart (_tag: %g unless it
            # reads back otherwise; adv48b g46: 30000000.000000004 and the
            # grid's 3e7 both printed 3e+07)
            raise UncertaintyError(
                "%s: entry 'pulses': (%s Pa, %s s) is not a point of the "
                "grid (overpressure %s Pa, duration %s s): the intervals are"
                " drawn on the study's own points" % (
                    w, _tag(A), _tag(T),
                    " ".join(_tag(x) for x in grid["overpressure"]),
                    " ".join(_tag(x) for x in grid["duration"])))
        if (A, T) in s["pulses"]:
            raise UncertaintyError("%s: entry 'pulses': (%s Pa, %s s) is "
                                   "given twice" % (w, _tag(A), _tag(T)))
        s["pulses"].append((A, T))
    variants = d.get("variants", {})
    if not isinstance(variants, dict):
        raise UncertaintyError("%s: entry 'variants' is not a "
                               "sub-dictionary" % w)
    s["variants"] = {n: _variant(n, v, mats, project, w + "/variants")
                     for n, v in variants.items()}
    s["parameters"] = []
    if "parameters" in d:
        params = d["parameters"]
        if not isinstance(params, dict) or not params:
            raise UncertaintyError("%s: entry 'parameters' is empty or not "
                                   "a sub-dictionary" % w)
        about = d.get("about", "base")
        if about != "base" and about not in s["variants"]:
            raise UncertaintyError(
                "%s: entry 'about' = %s: neither base nor a variant%s "
                "(variants: %s)" % (w, foamDict.format_value(about),
                                    foamDict.did_you_mean(
                                        str(about), list(s["variants"])),
                                    " ".join(s["variants"]) or "none"))
        s["about"] = about
        aboutMats = materialsOf(mats, s["variants"].get(about, {}))
        for name, p in params.items():
            pw = "%s/parameters/%s" % (w, name)
            region, entry = _parameterName(name, mats, pw)
            if not isinstance(p, dict):
                raise UncertaintyError("%s: not a sub-dictionary { interval "
                                       "(lo hi) [unit]; log yes|no; }" % pw)
            try:
                foamDict.check_keywords(p, PARAMETER_KEYWORDS, pw)
            except foamDict.DictError as err:
                raise UncertaintyError(str(err))
            unit = entryUnit(entry)
            if "interval" not in p:
                raise UncertaintyError("%s: no entry 'interval' (the "
                                       "calibration's 95 %% interval: "
                                       "interval (lo hi) [%s])" % (pw, unit))
            lohi = _withUnit(p["interval"], unit, pw + ": interval",
                             "interval (lo hi) [%s]" % unit)
            if not isinstance(lohi, list) or len(lohi) != 2 \
                    or not lohi[0] < lohi[1]:
                raise UncertaintyError("%s: interval %s: give (lo hi) with "
                                       "lo < hi [%s]" % (
                                           pw, foamDict.format_value(
                                               p["interval"]), unit))
            log = p.get("log", "yes")
            if log not in ("yes", "no", True, False):
                raise UncertaintyError("%s: log %s: yes or no"
                                       % (pw, foamDict.format_value(log)))
            log = log in ("yes", True)
            if log and not lohi[0] > 0:
                raise UncertaintyError("%s: log yes needs an interval above "
                                       "0, not (%g %g) %s"
                                       % (pw, lohi[0], lohi[1], unit))
            p0 = aboutMats[region][entry]
            if not isinstance(p0, (int, float)) or isinstance(p0, bool):
                raise UncertaintyError("%s: %s of the base case is not a "
                                       "number" % (pw, name))
            if log and not p0 > 0:
                raise UncertaintyError("%s: log yes: %s = %g %s at '%s' is "
                                       "not above 0" % (pw, name, p0, unit,
                                                        about))
            s["parameters"].append({
                "name": name, "region": region, "entry": entry,
                "unit": unit, "interval": tuple(lohi), "log": log,
                "value": float(p0),
                "halfWidth": (math.log(lohi[1]/lohi[0])/2 if log
                              else (lohi[1] - lohi[0])/2)})
        names = [p["name"] for p in s["parameters"]]
        n = len(names)
        R = np.eye(n)
        corr = d.get("correlation", [])
        # 'none': independent, as leaving the entry out (the user guide's
        # example; adv47b f64: refused as not a row)
        if corr == "none":
            corr = []
        if not isinstance(corr, list):
            corr = [corr]
        for c in corr:
            if not isinstance(c, list) or len(c) != 3 \
                    or c[0] not in names or c[1] not in names \
                    or c[0] == c[1] or isinstance(c[2], bool) \
                    or not isinstance(c[2], (int, float)) \
                    or not -1 <= c[2] <= 1:
                raise UncertaintyError(
                    "%s: entry 'correlation': %s is not (<parameter> "
                    "<another parameter> <correlation in [-1, 1]>) "
                    "(parameters: %s; 'none' or no entry: independent)"
                    % (w, foamDict.format_value(c),
                                          " ".join(names)))
            i, j = names.index(c[0]), names.index(c[1])
            if R[i, j] != 0:
                raise UncertaintyError("%s: entry 'correlation': %s %s is "
                                       "given twice" % (w, c[0], c[1]))
            R[i, j] = R[j, i] = float(c[2])
        if n and np.linalg.eigvalsh(R).min() < -1e-12:
            raise UncertaintyError("%s: entry 'correlation': the matrix is "
                                   "not positive semi-definite" % w)
        s["correlation"] = R
        s["independent"] = not corr
        diff = d.get("difference", "central")
        if diff not in ("central", "forward"):
            raise UncertaintyError("%s: entry 'difference' = %s: central or "
                                   "forward" % (w, foamDict.format_value(
                                       diff)))
        s["difference"] = diff
        for k in ("step", "checkStep"):
            if k not in d:
                raise UncertaintyError("%s: no entry '%s' (the finite "
                                       "difference's step in ln p or p/|p0|"
                                       " [-])" % (w, k))
            s[k] = _step(d, k, w)
        if s["step"] == s["checkStep"]:
            raise UncertaintyError("%s: entry 'checkStep' = step = %g: a "
                                   "second, other step checks the first"
                                   % (w, s["step"]))
        why = stepProblem(s)
        if why:
            raise UncertaintyError("%s: %s" % (w, why))
    else:
        for k in ("about", "correlation", "difference", "step",
                  "checkStep"):
            if k in d:
                raise UncertaintyError("%s: entry '%s' without 'parameters'"
                                       % (w, k))
    return s


def materialsOf(base, change):
    """The base materials with a change {region: {entry: value}}."""
    out = {r: dict(v) for r, v in base.items()}
    for r, e in change.items():
        out[r].update(e)
    return out


def _tag(x):
    """A step in a run's name: %g, unless two steps would then read the
    same (then every digit)."""
    return "%g" % x if float("%g" % x) == x else repr(float(x))


def runs(u):
    """The runs the uncertainty adds at each pulse: [(name, change)] with
    name the suffix of the point's label ('' for the grid's own run, not
    listed) and change {region: {entry: value}} against the base case."""
    out = [(n, v) for n, v in u["variants"].items()]
    if not u["parameters"]:
        return out
    about = u["about"]
    aboutChange = u["variants"].get(about, {})
    signs = (1, -1) if u["difference"] == "central" else (1,)
    for p in u["parameters"]:
        for h in (u["step"], u["checkStep"]):
            for sgn in signs:
                change = {r: dict(e) for r, e in aboutChange.items()}
                change.setdefault(p["region"], {})[p["entry"]] = \
                    perturbed(p, sgn*h)
                out.append(("%s_%s%s%s" % (about, p["name"],
                                           "+" if sgn > 0 else "-",
                                           _tag(h)), change))
    return out


def stepProblem(u):
    """Why a finite-difference step of u (its 'step' or 'checkStep') does
    not move every parameter, or None: a run of a parameter moved by the
    step whose value is the parameter's own in double precision (p e^(+-
    step) == p, p (1 +- step) == p) is the 'about' run again, its
    derivative 0 and the indicators' half-width 0, without a word (adv47b
    f25: step 1e-17). Names the entry, the parameter and the smallest step
    (a power of 2) that moves it both ways."""
    signs = (1, -1) if u["difference"] == "central" else (1,)
    for k in ("step", "checkStep"):
        h = u[k]
        for p in u["parameters"]:
            if all(perturbed(p, sgn*h) != p["value"] for sgn in signs):
                continue
            least = 2.0**-60
            while not all(perturbed(p, sgn*least) != p["value"]
                          for sgn in signs):
                least *= 2
            return ("entry '%s' = %g does not move parameter %s = %r %s: "
                    "%s is %r in double precision, so that run would be the "
                    "'about' run and the derivative 0 (the half-width 0). "
                    "Give a step of at least %r (a step much larger than "
                    "that: the derivative is a difference of the runs' "
                    "indicators, each known to some digits)"
                    % (k, h, p["name"], p["value"], p["unit"],
                       "%r e^(+-%g)" % (p["value"], h) if p["log"]
                       else "%r (1 +- %g)" % (p["value"], h),
                       p["value"], least))
    return None


def perturbed(p, dx):
    """The parameter p moved by dx in its fitted variable."""
    return p["value"]*math.exp(dx) if p["log"] \
        else p["value"] + dx*abs(p["value"])


def propagate(u, value):
    """The linearised 95 % interval of one indicator at one pulse: value
    (name) is the indicator of the run name ('base', a variant, or a name
    of runs()): a number, or an array (e.g. a time series on common
    times), the result then per element. Returns {'about', 'halfWidth',
    'derivatives' and 'contributions' (per parameter), 'halfWidthCheck',
    'derivativesCheck', 'contributionsCheck'}; NaN where a value is NaN."""
    about = u["about"]
    I0 = np.asarray(value(about), float)
    out = {"about": I0}
    R = u["correlation"]
    for key, h in (("", u["step"]), ("Check", u["checkStep"])):
        g = []
        for p in u["parameters"]:
            d = h if p["log"] else h*abs(p["value"])
            plus = np.asarray(value("%s_%s+%s" % (about, p["name"], _tag(h))),
                              float)
            if u["difference"] == "central":
                minus = np.asarray(value("%s_%s-%s" % (about, p["name"],
                                                       _tag(h))), float)
                g.append((plus - minus)/(2*d))
            else:
                g.append((plus - I0)/d)
        g = np.array(g)
        c = g*np.array([p["halfWidth"] for p in u["parameters"]]).reshape(
            (-1,) + (1,)*(g.ndim - 1))
        out["derivatives" + key] = g
        out["contributions" + key] = c
        out["halfWidth" + key] = np.sqrt(np.maximum(
            np.einsum("i...,ij,j...->...", c, R, c), 0.0))
    return out


def includeChange(case, change, label):
    """Write the change of a run to case/constant/solidProperties.
    pulseStudy and include it at the end of its solidProperties."""
    if not change:
        return
    lines = ["// pulseStudy: the material change of %s" % label,
             "materials", "{"]
    for r, e in change.items():
        lines.append("    %s" % r)
        lines.append("    {")
        for k, v in e.items():
            lines.append("        %-10s %s;    // [%s]"
                         % (k, repr(float(v)), entryUnit(k)))
        lines.append("    }")
    lines.append("}")
    props = os.path.join(case, "constant", "solidProperties")
    with open(props + ".pulseStudy", "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(props, "a") as f:
        f.write('\n#include "solidProperties.pulseStudy"\n')


_LOG_LINE = re.compile(r"^\s+(\w+): C10 (\S+) Pa, d0 (\S+) 1/Pa(.*)$", re.M)


def solverMaterials(log):
    """{region: {C10, mu1, tau1, ...}} the solver reports at its start
    (log.cellBlastFoam: '    nucleus: C10 6.67 Pa, d0 0 1/Pa, mu 431.12 Pa
    tau 0.5 s')."""
    with open(log, errors="replace") as f:
        text = f.read(200000)
    out = {}
    for m in _LOG_LINE.finditer(text):
        e = {"C10": float(m.group(2)), "d0": float(m.group(3))}
        for n, (mu, tau) in enumerate(re.findall(
                r"mu (\S+) Pa tau (\S+) s", m.group(4)), 1):
            e["mu%d" % n] = float(mu)
            e["tau%d" % n] = float(tau)
        out.setdefault(m.group(1), e)
    return out


def checkReached(log, change, label):
    """UncertaintyError if a changed C10, mu<N> or tau<N> is not what the
    solver reports it used (log.cellBlastFoam)."""
    used = solverMaterials(log)
    for r, e in change.items():
        for k, v in e.items():
            if k == "C10" or _BRANCH.match(k):
                got = used.get(r, {}).get(k)
                if got is None or abs(got - v) > 1e-12*abs(v):
                    raise UncertaintyError(
                        "%s: %s.%s = %r was asked for, the solver reports "
                        "%s (%s)" % (label, r, k, v, got, log))
