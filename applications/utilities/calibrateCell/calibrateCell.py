#!/usr/bin/python3
"""
Application
    calibrateCell

Description
    Fits material parameters of the indentation model (cellIndentationFoam)
    and the initial depth delta0 to measured forces: plateau forces (F_B,
    F_E), cycle peaks, or a force-time curve from a CSV file. Bounded
    trust-region least squares (scipy.optimize.least_squares, 'trf') on
    weighted residuals r = weight (F_model - F_target)/sigma, parameters
    optionally in log space, forward-difference Jacobian whose runs go in
    parallel. Reports the fitted values, the residuals, Jacobian-based
    standard errors and 95 % confidence intervals, and the correlation
    matrix (identifiability), and writes constant/solidProperties.calibrated
    (and constant/indenterProperties.calibrated when delta0 is fitted),
    postProcessing/calibration/{results.md, evaluations.csv,
    parameters.csv}.

    Exit code 0 converged, 2 not converged (results still written, marked),
    1 bad input or a failed forward run.

Usage
    calibrateCell [-case dir] [-dict file] [-nProcs N] [-keep] [-work dir]

    system/calibrationDict:
        nProcs              2;       // parallel forward runs [1, inf)
        maxIterations       30;      // trust-region function evaluations
                                     // [1, inf)
        tolerance           1e-6;    // ftol = xtol of least_squares (0, 1)
        finiteDifferenceStep 0.01;   // Jacobian step in the fitted
                                     // variable (log: 1 % of the value)
                                     // (0, 1]
        meshSizeFactor      1;       // cellMeshDict sizes scaled by it
                                     // (0, inf)
        relativeError       0.05;    // default sigma/value of the targets
        covariance          auto;    // auto | scaled | absolute
        // protocol ( ... );         // replaces the case's loading table

        parameters
        {
            cytoplasm.C10                 // <region>.<entry>: an entry of
            {                             // MaterialParameters [SI]
                value   1.67;             // initial (or fixed) value
                min     0.05;
                max     50;
                log     yes;              // fitted as ln(value)
                fit     yes;              // no: held at value
                scales  (cytoplasm.mu1);  // multiplied by value/initial
            }
            nucleusToCytoplasm            // <a>To<B>: a.C10 = value*b.C10
            { value 8; fit no; }
            delta0                        // first protocol row's depth [m]
            { value 1.41e-6; min 0.5e-6; max 3e-6; log no; }
        }
        targets                           // see targets.py
        {
            F_B { peak endB; value 0.3e-9; relativeError 0.05; }
            F_E { peak endE; value 1.67e-9; }
            curve { file "measured.csv"; sigma 0.02e-9; }
        }

\*---------------------------------------------------------------------------*/
"""

import argparse
import concurrent.futures
import math
import os
import shutil
import sys
import tempfile
import threading
import time

import numpy as np
from scipy import optimize, stats

try:
    from neuronFsi import script  # noqa: E402
except ImportError:
    sys.exit("calibrateCell.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from neuronFsi import caseLock, foamDict, indenterProperties, options, \
    ranges, signals  # noqa: E402
from forwardModel import ForwardModel, ModelError  # noqa: E402
from targets import RELATIVE_ERROR_RANGE, Targets, TargetError  # noqa: E402

UNITS = {"C10": "Pa", "d0": "1/Pa", "mu": "Pa", "tau": "s", "eta": "Pa s",
         "delta0": "m"}


class InputError(Exception):
    pass


# the largest span of a parameter's bounds in its fitted variable: ln(max/
# min) of a log parameter (1e30: 69), (max - min)/|value| of a linear one
MAX_SPAN = {True: math.log(1e30), False: 1e6}


def unit(name):
    if name == "delta0":
        return "m"
    if "." not in name:
        return "-"
    entry = name.split(".", 1)[1]
    return UNITS.get(entry if entry in UNITS else entry.rstrip("0123456789"),
                     "")


class Parameter:
    """One entry of 'parameters': its value, bounds and fitted variable
    x = ln(p/p_init) (log) or (p - p_init)/|p_init| (linear)."""

    def __init__(self, name, e, where):
        at = "%s: parameter '%s'" % (where, name)
        if not isinstance(e, dict):
            raise InputError("%s must be a sub-dictionary" % at)
        try:
            foamDict.check_keywords(
                e, ["value", "min", "max", "log", "fit", "scales"], at)
        except foamDict.DictError as err:
            raise InputError(str(err))
        self.name = name

        def switch(key, default):
            # a word other than a switch was taken as yes (adv30 k26:
            # 'fit maybe;' then refused as "'min' must be a number")
            v = e.get(key, default)
            if not isinstance(v, bool):
                raise InputError("%s: '%s' must be a switch (yes, no, true,"
                                 " false, on, off), not '%s'" % (at, key, v))
            return v

        self.fit = switch("fit", True)
        self.log = switch("log", False)

        def number(key, default=None):
            v = e.get(key, default)
            if v is None or isinstance(v, bool) \
                    or not isinstance(v, (int, float)):
                raise InputError("%s: '%s' must be a number, not '%s'"
                                 % (at, key, v))
            return float(v)

        self.initial = number("value")
        scales = e.get("scales", [])
        self.scales = [scales] if isinstance(scales, str) else list(scales)
        if not self.fit:
            self.lo = self.hi = self.initial
            return
        self.lo, self.hi = number("min"), number("max")
        if not self.lo < self.initial < self.hi:
            raise InputError("%s: value %g %s is not inside (min, max) = "
                             "(%g, %g)" % (at, self.initial, unit(name),
                                           self.lo, self.hi))
        if self.log and self.lo <= 0:
            raise InputError("%s: 'log yes' needs min > 0 (min = %g)"
                             % (at, self.lo))
        if not self.log and self.initial == 0:
            raise InputError("%s: a linear parameter needs a non-zero "
                             "initial value (its scale)" % at)
        # the fitted variable's bounds finite and of a size the optimiser
        # steps through: (max - min)/|value| of 1e599 (value 1e-299) was an
        # overflow in the fit (adv pass k36)
        span = (math.log(self.hi/self.lo) if self.log
                else (self.hi - self.lo)/abs(self.initial))
        if not span <= MAX_SPAN[self.log]:
            raise InputError("%s: (min, max) = (%g, %g) %s spans %s, more "
                             "than %g (%s): narrow the bounds%s"
                             % (at, self.lo, self.hi, unit(name),
                                "%.3g" % span, MAX_SPAN[self.log],
                                "ln(max/min)" if self.log else
                                "(max - min)/|value|",
                                "" if self.log else " or use 'log yes'"))

    def to_x(self, p):
        if self.log:
            return math.log(p/self.initial)
        return (p - self.initial)/abs(self.initial)

    def to_p(self, x):
        if self.log:
            return self.initial*math.exp(x)
        return self.initial + x*abs(self.initial)


def setting(d, key, default, where, interval, integer=False):
    """The number d[key] (default when absent), checked: a number (a whole
    one if integer), finite, inside interval ("(0, 1]": brackets as in
    mathematics, inf for no bound); InputError naming the dictionary, the
    entry, the value and the range otherwise."""
    v = d.get(key, default)
    if isinstance(v, foamDict.BelowReader) and not integer:
        raise InputError(v.problem(interval))
    kind = "a whole number" if integer else "a number"
    if isinstance(v, bool) or not isinstance(v, (int, float)) \
            or (integer and not isinstance(v, int)):
        raise InputError("%s: entry '%s' = '%s' is not %s (valid range %s)"
                         % (where, key, v, kind, interval))
    if v not in ranges.Interval(interval):
        raise InputError("%s: entry '%s' = %s is outside the valid range %s"
                         % (where, key, v, interval))
    return v


class Calibration:
    def __init__(self, case, dict_path, args):
        self.case = os.path.abspath(case)
        self.dict_path = dict_path
        try:
            d = foamDict.read(dict_path, belowReader=True)
        except (OSError, foamDict.DictError) as err:
            raise InputError(str(err))
        # a number OpenFOAM reads as 0: refused naming the entry's range by
        # the readers of the entries kept here (adv47b f30), any other now
        foamDict.refuseBelowReader(d, InputError, keep=(
            "tolerance", "finiteDifferenceStep", "relativeError",
            "meshSizeFactor",
            "targets/*/value", "targets/*/sigma", "targets/*/weight",
            "targets/*/relativeError"))
        self.d = d
        where = dict_path
        try:
            foamDict.check_keywords(
                d, ["nProcs", "maxIterations", "tolerance",
                    "finiteDifferenceStep", "covariance", "parameters",
                    "relativeError", "targets", "protocol",
                    "meshSizeFactor"], where)
        except foamDict.DictError as err:
            raise InputError(str(err))
        # -nProcs 0 is an error, not "unset"
        self.nprocs = args.nProcs if args.nProcs is not None \
            else setting(d, "nProcs", 2, where, "[1, inf)", integer=True)
        if self.nprocs < 1:
            raise InputError("%s: nProcs (or -nProcs) = %d is outside the "
                             "valid range [1, inf) (parallel forward runs)"
                             % (where, self.nprocs))
        # the optimiser's settings, checked before any run (adv28: k10
        # maxIterations -1 was scipy's traceback, k06 finiteDifferenceStep
        # 0 and k13 tolerance nan were accepted and the runs started)
        self.max_iter = setting(d, "maxIterations", 30, where, "[1, inf)",
                                integer=True)
        self.tol = setting(d, "tolerance", 1e-6, where, "(0, 1)")
        self.h = setting(d, "finiteDifferenceStep", 0.01, where, "(0, 1]")
        self.cov_mode = str(d.get("covariance", "auto"))
        if self.cov_mode not in ("auto", "scaled", "absolute"):
            raise InputError("%s: covariance '%s' is not valid (valid: "
                             "auto, scaled, absolute)" % (where,
                                                          self.cov_mode))
        if not isinstance(d.get("parameters"), dict) or not d["parameters"]:
            raise InputError("%s: 'parameters' must be a non-empty "
                             "sub-dictionary" % where)
        self.params = [Parameter(n, e, where)
                       for n, e in d["parameters"].items()]
        self.free = [p for p in self.params if p.fit]
        if not self.free:
            raise InputError("%s: no parameter has 'fit yes'" % where)
        rel = d.get("relativeError", 0.05)
        if isinstance(rel, foamDict.BelowReader):
            raise InputError(rel.problem(RELATIVE_ERROR_RANGE))
        self.targets = Targets(d.get("targets"), self.case, rel, where)
        if self.targets.size() < len(self.free):
            raise InputError("%s: %d target values for %d fitted "
                             "parameters: underdetermined"
                             % (where, self.targets.size(), len(self.free)))
        if self.cov_mode == "scaled" \
                and self.targets.size() <= len(self.free):
            raise InputError("%s: covariance scaled needs more target "
                             "values (%d) than fitted parameters (%d)"
                             % (where, self.targets.size(), len(self.free)))
        protocol = d.get("protocol")
        if protocol is not None and not (
                isinstance(protocol, list)
                and all(isinstance(r, list) and len(r) == 4
                        for r in protocol)):
            raise InputError("%s: 'protocol' must be a list of rows "
                             "(stage motion rate amount)" % where)
        self._check_curve_times(protocol, where)
        self._check_peak_labels(protocol, where)
        print("Forward model: cellIndentationFoam in %s" % args.work)
        self.model = ForwardModel(self.case, args.work,
                                  setting(d, "meshSizeFactor", 1.0, where,
                                          "(0, inf)"),
                                  protocol, args.keep, where)
        self._check_names(where)
        self.lock = threading.Lock()
        self.cache = {}
        self.history = []

    def _check_curve_times(self, protocol, where):
        """A measured curve ending after the protocol, refused before any
        forward run (adv32 k04: refused after the first one). The
        protocol's duration from its rows (neuronFsi.indenterProperties.
        protocolDuration), with a fitted delta0 at its min (the shortest
        run the fit may make); not known when stage A ends at a
        forceTarget (then checked after each forward run)."""
        src = "%s: entry 'protocol'" % where
        ip_path = os.path.join(self.case, "constant", "indenterProperties")
        try:
            ipd = foamDict.read(ip_path)
        except (OSError, foamDict.DictError):
            return          # the forward model's set-up names it
        if protocol is None:
            protocol = ipd.get("protocol")
            src = "%s: entry 'protocol'" % ip_path
        force_target = ipd.get("forceTarget", 0)
        if not isinstance(protocol, list) or (
                isinstance(force_target, (int, float))
                and force_target > 0):
            return
        delta0 = [p for p in self.params if p.name == "delta0"]
        first = delta0[0].lo if delta0 else None
        end = indenterProperties.protocolDuration(protocol, first)
        if end is None:
            return          # a bad row: cellIndentationFoam names it
        for it in self.targets.items:
            if it["kind"] == "curve" and it["time"][-1] > end*(1 + 1e-9):
                raise InputError(
                    "%s: the measured curve ends at %g s (its last row), "
                    "after the end of the protocol (%s), %g s%s: the "
                    "forward runs have no force there; valid times [0, %g] "
                    "s" % (it["file"], it["time"][-1], src, end,
                           " with delta0 at its min %g m" % first
                           if delta0 and delta0[0].fit else "", end))

    def _check_peak_labels(self, protocol, where):
        """Each peak target's label one of those the protocol's rows give
        peaks.dat (the dictionary's protocol, else the case's), before
        any forward run (adv46b d70)."""
        src = "%s: entry 'protocol'" % where
        if protocol is None:
            ip_path = os.path.join(self.case, "constant",
                                   "indenterProperties")
            try:
                protocol = foamDict.read(ip_path).get("protocol")
            except (OSError, foamDict.DictError):
                return          # the forward model's set-up names it
            src = "%s: entry 'protocol'" % ip_path
        if not isinstance(protocol, list):
            return              # cellIndentationFoam names it
        labels = indenterProperties.protocolPeakLabels(protocol)
        if labels is not None:
            self.targets.check_peaks(labels, src)

    def _check_names(self, where):
        regions = self.model.materials
        self.ratios = {}
        for p in self.params:
            targets = list(p.scales)
            if p.name == "delta0":
                if float(self.model.ip.get("forceTarget", 0)) > 0:
                    raise InputError(
                        "%s: delta0 is fitted but the case ends stage A at "
                        "forceTarget (constant/indenterProperties); remove "
                        "one of them" % where)
            elif "." in p.name:
                targets.append(p.name)
            else:
                parts = p.name.split("To", 1)
                if len(parts) != 2 or parts[0] not in regions \
                        or parts[1][:1].lower() + parts[1][1:] not in regions:
                    raise InputError(
                        "%s: parameter '%s' is not <region>.<entry>, "
                        "<region>To<Region> (ratio of C10) or delta0 "
                        "(regions: %s)" % (where, p.name,
                                           ", ".join(regions)))
                a, b = parts[0], parts[1][:1].lower() + parts[1][1:]
                if a == b:
                    # was: accepted, a.C10 = value*a.C10 (adv30 k25)
                    raise InputError(
                        "%s: parameter '%s' is the ratio of region '%s' to "
                        "itself; a ratio <a>To<B> needs two regions "
                        "(regions: %s)" % (where, p.name, a,
                                          ", ".join(regions)))
                if not p.lo > 0:
                    # a ratio of C10 at or below 0 (adv33 cc13: a forward
                    # run started, then the solver's "C10 = -1.67 Pa" of
                    # a temporary case quoted)
                    raise InputError(
                        "%s: parameter '%s' = %g%s (the ratio %s.C10/%s.C10)"
                        " must be positive: valid range (0, inf)"
                        % (where, p.name, p.lo, " (its min)" if p.fit
                           else "", a, b))
                self.ratios[p.name] = (a, b)
            for t in targets:
                region, _, entry = t.partition(".")
                if region not in regions:
                    raise InputError("%s: '%s': no region '%s' (regions: %s)"
                                     % (where, t, region, ", ".join(regions)))
                if entry == "c0":
                    raise InputError(
                        "%s: '%s': entry 'c0' is now 'C10' (the neo-Hookean "
                        "C10 = mu0/2, the paper's c_0): %s.C10"
                        % (where, t, region))
                if entry not in regions[region]:
                    raise InputError(
                        "%s: '%s': region '%s' has no entry '%s' (entries: "
                        "%s)" % (where, t, region, entry,
                                 ", ".join(regions[region])))
        direct = {p.name for p in self.params if "." in p.name}
        for name, (a, b) in self.ratios.items():
            if a + ".C10" in direct:
                raise InputError("%s: %s and %s.C10 both set %s.C10"
                                 % (where, name, a, a))
        # Each material entry is set by one parameter, once: a scale of the
        # fitted entry itself, or listed twice, applied its factor twice
        # (adv30 k18, k19)
        setters = {}
        for p in self.params:
            if "." in p.name:
                setters.setdefault(p.name, []).append(
                    "parameter '%s'" % p.name)
            for t in p.scales:
                setters.setdefault(t, []).append(
                    "'scales' of parameter '%s'" % p.name)
        for name, (a, b) in self.ratios.items():
            setters.setdefault(a + ".C10", []).append(
                "parameter '%s'" % name)
        for entry, by in setters.items():
            if len(by) > 1:
                raise InputError("%s: the entry %s is set %d times (by %s);"
                                 " each material entry can be set by one "
                                 "parameter, once"
                                 % (where, entry, len(by), ", ".join(by)))

    # -- parameters -> model inputs ----------------------------------------
    def values(self, x):
        v = {p.name: p.initial for p in self.params}
        for p, xi in zip(self.free, x):
            v[p.name] = p.to_p(xi)
        return v

    def materials(self, v):
        mats = {r: dict(e) for r, e in self.model.materials.items()}
        for p in self.params:
            if "." in p.name:
                region, _, entry = p.name.partition(".")
                mats[region][entry] = v[p.name]
        for p in self.params:
            for t in p.scales:
                region, _, entry = t.partition(".")
                mats[region][entry] *= v[p.name]/p.initial
        for name, (a, b) in self.ratios.items():
            mats[a]["C10"] = v[name]*mats[b]["C10"]
        return mats

    # -- evaluations ----------------------------------------------------------
    def evaluate(self, x, kind):
        key = tuple(np.round(x, 12))
        with self.lock:
            if key in self.cache:
                return self.cache[key]
            n = len(self.history) + 1
            self.history.append(None)
        v = self.values(x)
        run = self.model.run(self.materials(v), v.get("delta0"),
                             tag="eval%04d" % n)
        r = self.targets.residuals(run)
        rec = dict(n=n, kind=kind, values=v, run=run, r=r,
                   norm=float(np.linalg.norm(r)))
        with self.lock:
            self.history[n - 1] = rec
            self.cache[key] = rec
            print("eval %3d %-3s %s  |r| = %.4e  wall %.1f s"
                  % (n, kind, "  ".join(
                      "%s = %.5g %s" % (p.name, v[p.name], unit(p.name))
                      for p in self.free), rec["norm"], run["wall"]),
                  flush=True)
        return rec

    def fun(self, x):
        return self.evaluate(x, "f")["r"]

    def jac(self, x):
        """Forward differences, the n runs in parallel; a step that would
        leave the bounds goes backwards."""
        base = self.evaluate(x, "f")
        steps = []
        for j, p in enumerate(self.free):
            h = self.h
            if x[j] + h > p.to_x(p.hi):
                h = -h
            xj = np.array(x, dtype=float)
            xj[j] += h
            steps.append((xj, h))
        with concurrent.futures.ThreadPoolExecutor(self.nprocs) as pool:
            recs = list(pool.map(lambda s: self.evaluate(s[0], "J"), steps))
        J = np.empty((len(base["r"]), len(self.free)))
        for j, (rec, (_, h)) in enumerate(zip(recs, steps)):
            J[:, j] = (rec["r"] - base["r"])/h
        return J

    # -- fit and report -------------------------------------------------------
    def run(self):
        t0 = time.time()
        x0 = np.zeros(len(self.free))
        lo = np.array([p.to_x(p.lo) for p in self.free])
        hi = np.array([p.to_x(p.hi) for p in self.free])
        print("Fitting %s to %d target values (%d forward runs in parallel, "
              "%d elements)" % (", ".join(p.name for p in self.free),
                                self.targets.size(), self.nprocs,
                                self.model.elements), flush=True)
        res = optimize.least_squares(
            self.fun, x0, jac=self.jac, bounds=(lo, hi), method="trf",
            ftol=self.tol, xtol=self.tol, gtol=self.tol,
            max_nfev=self.max_iter, x_scale=1.0)
        self.wall = time.time() - t0
        return self.report(res)

    def covariance(self, J, r):
        m, n = J.shape
        mode = self.cov_mode
        if mode == "auto":
            mode = "scaled" if m > n else "absolute"
        s2 = float(r @ r)/(m - n) if mode == "scaled" else 1.0
        _, sv, Vt = np.linalg.svd(J, full_matrices=False)
        singular = sv[-1] <= sv[0]*max(m, n)*np.finfo(float).eps
        cov = np.full((n, n), np.inf) if singular else \
            (Vt.T/sv**2) @ Vt*s2
        q = stats.t.ppf(0.975, m - n) if mode == "scaled" else \
            stats.norm.ppf(0.975)
        cond = np.inf if singular else sv[0]/sv[-1]
        return cov, q, mode, s2, cond, singular

    def report(self, res):
        converged = res.status > 0
        status = {0: "the maximum number of evaluations (maxIterations %d) "
                     "was reached" % self.max_iter,
                  1: "gradient below tolerance", 2: "cost change below "
                  "tolerance", 3: "parameter change below tolerance",
                  4: "cost and parameter change below tolerance"
                  }.get(res.status, res.message)
        best = self.evaluate(res.x, "f")
        J, r = res.jac, best["r"]
        cov, q, mode, s2, cond, singular = self.covariance(J, r)
        v = best["values"]
        model = self.targets.model_values(best["run"])
        data = np.concatenate([it["value"] for it in self.targets.items])
        L = []
        L.append("# Calibration of %s" % os.path.basename(self.case))
        L.append("")
        if converged:
            L.append("Converged: %s (%d trust-region evaluations, %d "
                     "forward runs, wall %.0f s, %d elements)."
                     % (status, res.nfev, len(self.history), self.wall,
                        self.model.elements))
        else:
            L.append("**NOT CONVERGED**: %s (%d trust-region evaluations, "
                     "%d forward runs, wall %.0f s). The values below are "
                     "the last iterate, not a minimum."
                     % (status, res.nfev, len(self.history), self.wall))
        at_bound = [p.name for p, a in zip(self.free, res.active_mask) if a]
        if at_bound:
            L.append("")
            L.append("At a bound (its interval is not meaningful): %s."
                     % ", ".join(at_bound))
        L.append("")
        L.append("Residual norm |r| = %.4g (r = weight (F_model - "
                 "F_target)/sigma); covariance %s (s^2 = %.4g), 95 %% "
                 "quantile %.3f; condition number of J %.3g."
                 % (best["norm"], mode, s2, q, cond))
        L.append("")
        L.append("| parameter | initial | fitted | standard error | 95 % "
                 "interval | unit |")
        L.append("|---|---|---|---|---|---|")
        self.fitted = []
        for j, p in enumerate(self.free):
            se_x = math.sqrt(cov[j, j]) if np.isfinite(cov[j, j]) \
                else float("inf")
            x = p.to_x(v[p.name])
            lo, hi = p.to_p(x - q*se_x) if np.isfinite(se_x) else -np.inf, \
                p.to_p(x + q*se_x) if np.isfinite(se_x) else np.inf
            if p.log and not np.isfinite(se_x):
                lo = 0.0
            se = (v[p.name]*se_x if p.log else abs(p.initial)*se_x)
            self.fitted.append((p, v[p.name], se, lo, hi))
            L.append("| %s | %.5g | %.5g | %.3g%s | [%.5g, %.5g] | %s |"
                     % (p.name, p.initial, v[p.name], se,
                        " (log: %.3g)" % se_x if p.log else "", lo, hi,
                        unit(p.name)))
        fixed = [p for p in self.params if not p.fit]
        if fixed:
            L.append("")
            L.append("Held fixed: " + ", ".join(
                "%s = %.5g %s" % (p.name, p.initial, unit(p.name))
                for p in fixed) + ".")
        if singular:
            L.append("")
            L.append("**Not identifiable**: the Jacobian is singular; the "
                     "targets do not determine all fitted parameters.")
        if len(self.free) > 1:
            corr = cov/np.sqrt(np.outer(np.diag(cov), np.diag(cov))) \
                if not singular else np.full(cov.shape, np.nan)
            L.append("")
            L.append("Correlation matrix of the fitted variables:")
            L.append("")
            L.append("| | " + " | ".join(p.name for p in self.free) + " |")
            L.append("|---" * (len(self.free) + 1) + "|")
            for i, p in enumerate(self.free):
                L.append("| %s | " % p.name + " | ".join(
                    "%.3f" % c for c in corr[i]) + " |")
            strong = [(self.free[i].name, self.free[k].name, corr[i, k])
                      for i in range(len(self.free))
                      for k in range(i + 1, len(self.free))
                      if abs(corr[i, k]) > 0.95]
            for a, b, c in strong:
                L.append("")
                L.append("Poorly identifiable: %s and %s correlated %.3f "
                         "(the targets fix a combination of them)."
                         % (a, b, c))
        L.append("")
        L.append("| target | model [N] | target [N] | difference | "
                 "residual |")
        L.append("|---|---|---|---|---|")
        labels = self.targets.labels()
        rows = range(len(data)) if len(data) <= 20 else \
            np.linspace(0, len(data) - 1, 20).astype(int)
        for i in rows:
            L.append("| %s | %.4g | %.4g | %+.2f %% | %+.3g |"
                     % (labels[i], model[i], data[i],
                        100*(model[i]/data[i] - 1) if data[i] else 0, r[i]))
        if len(data) > 20:
            L.append("")
            L.append("(20 of %d curve points shown)" % len(data))
        mats = self.model.materials
        cal = self.materials(v)
        L.append("")
        L.append("| region | entry | case [SI] | calibrated [SI] | ratio |")
        L.append("|---|---|---|---|---|")
        for region in cal:
            for k in cal[region]:
                if cal[region][k] != mats[region][k]:
                    L.append("| %s | %s | %.5g | %.5g | %.4f |"
                             % (region, k, mats[region][k], cal[region][k],
                                cal[region][k]/mats[region][k]
                                if mats[region][k] else float("nan")))
        if "delta0" in v:
            L.append("")
            L.append("delta0 = %.5g m" % v["delta0"])
        text = "\n".join(L) + "\n"
        print("\n" + text)
        self.write(cal, v, text)
        return 0 if converged else 2

    def write(self, cal, v, text):
        header = ("// Written by calibrateCell (fit to the targets of %s):\n"
                  "// every region's material below\n"
                  % os.path.relpath(self.dict_path, self.case))
        sp = self.model.solid_properties(cal)
        i = sp.find("\n", sp.find("\\*---"))
        sp = sp[:i + 1] + header + sp[i + 1:]
        out = os.path.join(self.case, "constant/solidProperties.calibrated")
        # by replacement: a link there is replaced, never written through
        # (adv44 a17: the user's shared file outside the case written over)
        with script.replacing(out) as f:
            f.write(sp)
        written = [out]
        if "delta0" in v:
            out = os.path.join(self.case,
                               "constant/indenterProperties.calibrated")
            with script.replacing(out) as f:
                f.write(self.model.indenter_properties(v["delta0"]))
            written.append(out)
        pp = os.path.join(self.case, "postProcessing/calibration")
        os.makedirs(pp, exist_ok=True)
        with script.replacing(os.path.join(pp, "results.md")) as f:
            f.write(text)
        with script.replacing(os.path.join(pp, "evaluations.csv")) as f:
            f.write("evaluation,kind," + ",".join(
                "%s [%s]" % (p.name, unit(p.name)) for p in self.free)
                + ",residual norm,wall [s],cpu [s]\n")
            for rec in self.history:
                if rec is None:
                    continue
                f.write("%d,%s,%s,%.6g,%.2f,%.2f\n" % (
                    rec["n"], rec["kind"], ",".join(
                        "%.8g" % rec["values"][p.name] for p in self.free),
                    rec["norm"], rec["run"]["wall"], rec["run"]["cpu"]))
        with script.replacing(os.path.join(pp, "parameters.csv")) as f:
            f.write("parameter,unit,initial,fitted,standard error,"
                    "95% low,95% high\n")
            for p, value, se, lo, hi in self.fitted:
                f.write("%s,%s,%.10g,%.10g,%.6g,%.10g,%.10g\n"
                        % (p.name, unit(p.name), p.initial, value, se, lo,
                           hi))
        written += [os.path.join(pp, f) for f in
                    ("results.md", "evaluations.csv", "parameters.csv")]
        print("Written:\n    " + "\n    ".join(
            os.path.relpath(w) for w in written))


def main():
    ap = argparse.ArgumentParser(
        prog="calibrateCell", description="Fit the indentation model's "
        "parameters to measured forces (system/calibrationDict)")
    ap.add_argument("-case", default=".", help="case directory")
    ap.add_argument("-dict", help="calibration dictionary (default "
                    "<case>/system/calibrationDict)")
    ap.add_argument("-nProcs", type=int, help="parallel forward runs "
                    "(default: the dictionary's nProcs, else 2)")
    ap.add_argument("-work", help="scratch folder (default: a new "
                    "temporary one)")
    ap.add_argument("-keep", action="store_true",
                    help="keep the run folders")
    args = options.parse(ap)
    if args.dict is not None and not os.path.isfile(args.dict):
        # was "[Errno 21] Is a directory: 'system'", naming no option; a
        # FIFO blocked the open (options.notARegularFile)
        kind = options.notARegularFile(args.dict)
        print("calibrateCell: error: -dict %s: %s; the option's value must "
              "be a calibration dictionary file (default "
              "<case>/system/calibrationDict)"
              % (args.dict, kind + ", not a file" if kind
                 else "no such file"),
              file=sys.stderr)
        return 1
    dict_path = args.dict or os.path.join(args.case,
                                          "system/calibrationDict")
    # the solvers' run lock of the case (neuronFsi.caseLock), held while
    # the calibration reads and writes it
    try:
        lock = caseLock.held(args.case, "calibrateCell").__enter__()
    except caseLock.CaseLockError as err:
        print("calibrateCell: error: %s" % err, file=sys.stderr)
        return 1
    own = args.work is None
    try:
        args.work = args.work or tempfile.mkdtemp(prefix="calibrateCell.")
        return Calibration(args.case, dict_path, args).run()
    except ModelError as err:
        # the scratch folder stays when the message may point into it:
        # when it holds more than the forward model's marker (adv45 c05
        # (a): a case refused before anything was written left an empty
        # /tmp/calibrateCell.X)
        print("calibrateCell: error: %s" % err, file=sys.stderr)
        own = own and args.work is not None and os.path.isdir(args.work) \
            and not [n for n in os.listdir(args.work)
                     if n != ".calibrateCellWork"]
        return 1
    except (InputError, TargetError, foamDict.DictError) as err:
        print("calibrateCell: error: %s" % err, file=sys.stderr)
        return 1
    finally:
        # our own temporary scratch folder; kept with -keep
        if own and args.work and not args.keep:
            shutil.rmtree(args.work, ignore_errors=True)
        lock.__exit__(None, None, None)


if __name__ == "__main__":
    # SIGTERM, SIGHUP, SIGINT end the runs started (signals.call) and exit
    # 128 + the signal (adv28 z3: planeWave's run was left running)
    with signals.stopOn("calibrateCell"):
        sys.exit(main())
