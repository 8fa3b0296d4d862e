"""Calibration targets of calibrateCell: forces from peaks.dat (a stage end
or a cycle peak) and measured force-time curves from CSV files, each with
its uncertainty sigma [N]; the weighted residuals of a forward run."""

import csv
import os
import re

import numpy as np

from neuronFsi import foamDict, options, ranges


class TargetError(Exception):
    """A bad target; the message names the file and the entry/column/row."""


def _header_name(cell):
    """'time [s]' -> ('time', 's'); 'Force(N)' -> ('force', 'N'); 'time'
    -> ('time', '')."""
    m = re.match(r"\s*([^\[(]*?)\s*(?:[\[(]\s*([^\])]*?)\s*[\])])?\s*$",
                 cell)
    if not m:
        return cell.strip().lower(), None
    return m.group(1).lower(), m.group(2) or ""


# a target force [N]: a cell's contact force is pN to nN; 1 mN would
# crush it
FORCE_RANGE = "[1e-15, 1e-3]"
FORCE_MAX = 1e-3
# a target's relativeError (and the dictionary's default of it)
RELATIVE_ERROR_RANGE = "[1e-6, 10]"

# the units of the columns read: SI only (a curve in ms and nN was read as
# s and N without a word, adv32 k01, k01b)
CURVE_UNITS = {"time": "s", "force": "N"}


def read_curve(path):
    """Times [s] and forces [N] of a CSV file with a header row naming the
    columns 'time' and 'force' (units in brackets allowed, other columns
    ignored). Times strictly increasing, forces finite and >= 0."""
    why = options.fileProblem(path)
    if why:
        raise TargetError("%s: %s" % (path, why))
    # utf-8-sig: a byte-order mark (spreadsheet exports) is not part of
    # the first column's name (adv32 k02: "missing column 'time'")
    try:
        with open(path, newline="", encoding="utf-8-sig") as f:
            rows = [r for r in csv.reader(f)
                    if r and any(c.strip() for c in r)]
    except UnicodeDecodeError as err:
        raise TargetError("%s: not a UTF-8 text file (byte %d): expected a "
                          "CSV file with the columns 'time [s]' and "
                          "'force [N]'" % (path, err.start))
    if not rows:
        raise TargetError("%s: empty file (expected a header row with the "
                          "columns 'time [s]' and 'force [N]')" % path)
    # a spreadsheet export with another separator (';' in many locales, a
    # tab): one column (adv34 n15: reported as "missing column 'time'")
    if len(rows[0]) == 1:
        for sep, name in ((";", "';'"), ("\t", "tabs")):
            if sep in rows[0][0]:
                raise TargetError(
                    "%s: the columns of its header row are separated by %s, "
                    "not by commas (header row: %s): calibrateCell reads "
                    "comma-separated values; export the file with ',' as "
                    "the separator (and '.' as the decimal mark)"
                    % (path, name, rows[0][0]))
    heads = [_header_name(c) for c in rows[0]]
    names = [h[0] for h in heads]
    for want in ("time", "force"):
        if names.count(want) > 1:
            # was: the first one used, without a word (adv30 k15)
            raise TargetError("%s: column '%s' is given %d times (header "
                              "row: %s, columns %s); give it once"
                              % (path, want, names.count(want),
                                 ", ".join(rows[0]),
                                 " and ".join(str(k + 1) for k, n in
                                              enumerate(names)
                                              if n == want)))
    cols = {}
    for want in ("time", "force"):
        if want not in names:
            raise TargetError("%s: missing column '%s' (header row: %s; "
                              "expected 'time [s]' and 'force [N]')"
                              % (path, want, ", ".join(rows[0])))
        cols[want] = names.index(want)
        unitGiven = heads[cols[want]][1]
        if unitGiven not in ("", CURVE_UNITS[want]):
            raise TargetError(
                "%s: column '%s' (header '%s', column %d) is in '%s': the "
                "valid unit is [%s] (or none: SI); convert the column to %s"
                % (path, want, rows[0][cols[want]].strip(),
                   cols[want] + 1, unitGiven, CURVE_UNITS[want],
                   CURVE_UNITS[want]))
    t, F = [], []
    for n, r in enumerate(rows[1:], start=2):
        vals = {}
        for want, c in cols.items():
            if c >= len(r):
                raise TargetError("%s, row %d: no value in column '%s'"
                                  % (path, n, want))
            try:
                vals[want] = float(r[c])
            except ValueError:
                raise TargetError("%s, row %d, column '%s': '%s' is not a "
                                  "number" % (path, n, want, r[c].strip()))
            # as a dictionary's numbers (5e-324 became a division by
            # zero: adv pass k33)
            why = ranges.readerRangeProblem(r[c].strip(), vals[want])
            if why:
                raise TargetError("%s, row %d, column '%s': %s %s"
                                  % (path, n, want, r[c].strip(), why))
            if not np.isfinite(vals[want]):
                raise TargetError("%s, row %d, column '%s': %s is not "
                                  "finite" % (path, n, want, r[c].strip()))
        if vals["force"] < 0:
            raise TargetError("%s, row %d, column 'force': negative force "
                              "%g N" % (path, n, vals["force"]))
        # a cell's contact force: a force of 1e300 N overflowed in the
        # report (adv32 k11)
        if vals["force"] > FORCE_MAX:
            raise TargetError("%s, row %d, column 'force': %g N is outside "
                              "the valid range [0, %g] N (a cell's contact "
                              "force: pN to nN; the column must be in N)"
                              % (path, n, vals["force"], FORCE_MAX))
        # the protocol starts at 0 s (adv32 k03: negative times accepted)
        if vals["time"] < 0:
            raise TargetError("%s, row %d, column 'time': %g s is before "
                              "the protocol's start: the valid range is "
                              "[0, the protocol's end] s"
                              % (path, n, vals["time"]))
        if t and vals["time"] <= t[-1]:
            raise TargetError("%s, row %d, column 'time': time %g s is not "
                              "after the previous row's %g s (time must "
                              "increase monotonically)"
                              % (path, n, vals["time"], t[-1]))
        t.append(vals["time"])
        F.append(vals["force"])
    if not t:
        raise TargetError("%s: no data rows below the header" % path)
    return np.array(t), np.array(F)




def _sigmaAgainst(at, sigma, force):
    """sigma [N] at least 1e-6 of the target's force: a smaller one makes
    the residual's scale 1e6/force or more (adv pass k34: the fit
    overflowed)."""
    if sigma < 1e-6*force:
        raise TargetError("%s: sigma = %g N is outside the valid range "
                          "[%g, 1] N (at least 1e-6 of the target's force, "
                          "%g N)" % (at, sigma, 1e-6*force, force))


class Targets:
    """All targets of a calibrationDict 'targets' sub-dictionary.

    Entries (each target a sub-dictionary named by the user):
        peak          label of peaks.dat (endB, endE, C1,i, ...); with
        value         the target force [N] (> 0)
        file          or: CSV file of a measured force-time curve
                      (relative to the case directory)
        sigma         uncertainty [N] of the value / of each curve point
        relativeError or: sigma = relativeError*value (curve: *max force)
        weight        residual multiplier [-] (> 0, default 1)
    Residual r = weight (F_model - F_target)/sigma.
    """

    def __init__(self, entries, case, relative_error, where):
        if not isinstance(entries, dict) or not entries:
            raise TargetError("%s: 'targets' must be a non-empty "
                              "sub-dictionary" % where)
        self.items = []
        for name, e in entries.items():
            self.items.append(self._read(name, e, case, relative_error,
                                         where))
        # One target per force: a second target on the same peak or
        # curve would count its force twice in the fit
        seen = {}
        for it in self.items:
            key = (it["kind"], it["peak"] if it["kind"] == "peak"
                   else os.path.realpath(it["file"]))
            if key in seen:
                raise TargetError(
                    "%s: targets '%s' and '%s' both fit the %s '%s' (a "
                    "force counted twice: give one target per peak or "
                    "curve, with 'weight' to weigh it)"
                    % (where, seen[key], it["name"],
                       "peak" if it["kind"] == "peak" else "curve file",
                       it["peak"] if it["kind"] == "peak" else it["file"]))
            seen[key] = it["name"]

    @staticmethod
    def _read(name, e, case, relative_error, where):
        at = "%s: target '%s'" % (where, name)
        if not isinstance(e, dict):
            raise TargetError("%s must be a sub-dictionary" % at)
        try:
            foamDict.check_keywords(
                e, ["peak", "value", "file", "sigma", "relativeError",
                    "weight"], at)
        except foamDict.DictError as err:
            raise TargetError(str(err))

        def positive(key, default=None, interval="(0, inf)", unit=""):
            v = e.get(key, default)
            if v is None:
                return None
            if isinstance(v, foamDict.BelowReader):
                raise TargetError(v.problem(interval, unit))
            # inf, nan, a word: named with the valid range (adv48a h15:
            # "'relativeError' must be a number, not 'inf'")
            if isinstance(v, bool) or not isinstance(v, (int, float)) \
                    or not np.isfinite(v):
                raise TargetError("%s: '%s' = %s is not a number in the "
                                  "valid range %s%s"
                                  % (at, key, foamDict.format_value(v),
                                     interval, unit))
            if v not in ranges.Interval(interval):
                raise TargetError("%s: '%s' = %g%s is outside the valid "
                                  "range %s%s" % (at, key, v, unit,
                                                  interval, unit))
            return float(v)

        # finite ranges: a residual weight/sigma (F - F_target) of 1e-300
        # or 1e300 overflowed in the fit (adv pass k33, k34, k36)
        weight = positive("weight", 1.0, "[1e-6, 1e6]")
        sigma = positive("sigma", None, "(0, 1]", " N")
        rel = positive("relativeError", relative_error, RELATIVE_ERROR_RANGE)
        if "file" in e:
            if "peak" in e or "value" in e:
                raise TargetError("%s: give either 'file' (a curve) or "
                                  "'peak' and 'value', not both" % at)
            path = os.path.join(case, str(e["file"]))
            t, F = read_curve(path)
            if sigma is None:
                if rel is None:
                    raise TargetError("%s: give 'sigma' [N] or "
                                      "'relativeError'" % at)
                sigma = rel*float(np.max(F))
                if sigma <= 0:
                    raise TargetError("%s: all forces in %s are zero; give "
                                      "'sigma' [N]" % (at, path))
            _sigmaAgainst(at, sigma, float(np.max(F)))
            return dict(name=name, kind="curve", file=path, time=t,
                        value=F, sigma=np.full(len(t), sigma),
                        weight=weight)
        if "peak" not in e or "value" not in e:
            raise TargetError("%s: give 'peak' (a label of peaks.dat) and "
                              "'value' [N], or 'file' (a CSV curve)" % at)
        v = e["value"]
        if isinstance(v, foamDict.BelowReader):
            raise TargetError(v.problem(FORCE_RANGE, " N"))
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise TargetError("%s: 'value' must be a force [N], not '%s'"
                              % (at, v))
        if not np.isfinite(v):
            raise TargetError("%s: 'value' = %s is not a finite force [N] "
                              "(valid range (0, inf) N)" % (at, v))
        if v <= 0:
            raise TargetError("%s: 'value' = %g N: a target force must be "
                              "positive (compressive contact force)"
                              % (at, v))
        if v not in ranges.Interval(FORCE_RANGE):
            raise TargetError("%s: 'value' = %g N is outside the valid range"
                              " %s N (a cell's contact force: pN to nN)"
                              % (at, v, FORCE_RANGE))
        if sigma is None:
            if rel is None:
                raise TargetError("%s: give 'sigma' [N] or "
                                  "'relativeError'" % at)
            sigma = rel*v
        _sigmaAgainst(at, sigma, v)
        return dict(name=name, kind="peak", peak=str(e["peak"]),
                    value=np.array([float(v)]), sigma=np.array([sigma]),
                    weight=weight)

    def size(self):
        return sum(len(it["value"]) for it in self.items)

    def check_peaks(self, labels, src):
        """TargetError naming the first peak target whose label is not one
        of labels, the peaks.dat labels of the protocol src (neuronFsi.
        indenterProperties.protocolPeakLabels), before any forward run
        (adv46b d70: 'endX' was refused after the first runs, ~2.5 min)."""
        for it in self.items:
            if it["kind"] == "peak" and it["peak"] not in labels:
                raise TargetError(
                    "target '%s': peak '%s' is not a peak of the protocol "
                    "(%s), whose peaks.dat labels are: %s%s (a load row "
                    "followed by an unload row of its stage is '<stage>,i', "
                    "',ii', ...; a hold row ending its stage 'end<stage>'). "
                    "Nothing was run"
                    % (it["name"], it["peak"], src,
                       ", ".join(labels) or "none",
                       foamDict.did_you_mean(it["peak"], labels)))

    def model_values(self, run):
        """Model forces [N] at the targets from a forward run (dict with
        'peaks': label -> force, 'time', 'force' arrays)."""
        out = []
        for it in self.items:
            if it["kind"] == "peak":
                if it["peak"] not in run["peaks"]:
                    raise TargetError(
                        "target '%s': no peak '%s' in peaks.dat of the "
                        "forward run (labels: %s); does the protocol reach "
                        "it?" % (it["name"], it["peak"],
                                 ", ".join(run["peaks"])))
                out.append([run["peaks"][it["peak"]]])
            else:
                t = np.concatenate(([0.0], run["time"]))
                F = np.concatenate(([0.0], run["force"]))
                if it["time"][-1] > t[-1]*(1 + 1e-9):
                    raise TargetError(
                        "target '%s': %s ends at %g s, after the forward "
                        "run's protocol (%g s)"
                        % (it["name"], it["file"], it["time"][-1], t[-1]))
                out.append(np.interp(it["time"], t, F))
        return np.concatenate(out)

    def residuals(self, run):
        model = self.model_values(run)
        data = np.concatenate([it["value"] for it in self.items])
        scale = np.concatenate([it["weight"]/it["sigma"]
                                for it in self.items])
        return scale*(model - data)

    def labels(self):
        out = []
        for it in self.items:
            if it["kind"] == "peak":
                out.append("%s (%s)" % (it["name"], it["peak"]))
            else:
                out += ["%s t=%g s" % (it["name"], t) for t in it["time"]]
        return out
