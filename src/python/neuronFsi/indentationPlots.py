"""The indentation scene's plots and numbers (paper Figs. 4-8, Table 3):
what tutorials/indentation/plotIndentation.py, plotFields.py and the
paper comparison (applications/utilities/paperFigures) share.

    rows, peaks = read(case)      postProcessing/indentation/force.dat
                                  (time, depth, force, stage rows) and
                                  peaks.dat ({label: (time, depth, force)})
    forceDepth(case, rows, out)   force against depth per rate (C1, C2, C3:
                                  the paper's Figs. 4-6) and against time
    f = fields(case, time)        the solid of postProcessing/indentation/
                                  solid.h5 at a write (Fields)
    fieldsFigure(f, out, title)   its r-z section (deformed) coloured by
                                  the element pressure and von Mises stress

SI units in and out (the plots in um, nN, Pa).
"""
import os

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection

from . import script
from . import msh, postProcessing, resultDigest
from .solidResults import SolidResults, SolidResultsError

RATES = {"C1": "10 um/s", "C2": "1 um/s", "C3": "0.1 um/s"}


class IndentationPlotError(Exception):
    """A result that cannot be read or lacks what is asked; the message
    names the file."""


def _runIds(d):
    """{file: run id} of force.dat and peaks.dat (their first line "# run
    <id>") and solid.h5 (its root attribute runId) in d, those that have
    one."""
    ids = {}
    for name in ("force.dat", "peaks.dat"):
        try:
            with open(os.path.join(d, name), errors="replace") as f:
                first = f.readline(4096)
        except OSError:
            continue
        if first.startswith("# run "):
            ids[name] = first[6:].strip()
    h5 = os.path.join(d, "solid.h5")
    if os.path.isfile(h5):
        try:
            import h5py
            with h5py.File(h5, "r") as f:
                v = f.attrs.get("runId")
            if v is not None:
                ids["solid.h5"] = v.decode() if isinstance(v, bytes) \
                    else str(v)
        except (OSError, ImportError):
            pass        # solid.h5's own readers name its damage
    return ids


def _sameRun(d):
    """A DigestError unless force.dat, peaks.dat and solid.h5 of d name one
    run (adv54 n03 (a): another case's force.dat and peaks.dat copied with
    their digests into a finished case were tabled as its own), unless
    the script measures hand-made files."""
    if resultDigest._handMade:
        return
    ids = _runIds(d)
    if len(set(ids.values())) > 1:
        raise resultDigest.DigestError(
            "%s: its results are of different runs: %s. A file copied from "
            "another run (another case, or an earlier start) is not this "
            "case's result; restore the run's own files, or give %s to "
            "measure them as they are" % (
                d, "; ".join("%s names run %s" % (k, v)
                             for k, v in sorted(ids.items())),
                resultDigest._option or "-acceptHandMade"))


def read(case):
    """(rows, peaks) of an indentation case: rows [(time [s], depth [m],
    force [N], stage)] of force.dat, peaks {label: (time [s], depth [m],
    force [N])} of peaks.dat. Each as cellIndentationFoam wrote it (its
    digests, force.dat.fnv1a64 and peaks.dat.fnv1a64: resultDigest.check;
    adv52 p31: peaks.dat x1.5 was plotted and tabled), unless the script's
    option accepts hand-made files."""
    d = os.path.join(case, "postProcessing", "indentation")
    try:
        resultDigest.checkFinished(case, "postProcessing/indentation")
        for name in ("force.dat", "peaks.dat"):
            # rows after the last digest line: appended, or a run going on
            # (adv54 n01, n10)
            path = os.path.join(d, name)
            resultDigest.uncoveredRows(path, resultDigest.check(path))
        _sameRun(d)
        f = postProcessing.readTable(os.path.join(d, "force.dat"))
        # times increasing, numbers finite (adv32 pl01, pl02: nan forces
        # and times going back were plotted, exit 0)
        rows = list(zip(f.column("time", increasing=True),
                        f.column("depth", finite=True),
                        f.column("force", finite=True), f.column("stage")))
        p = postProcessing.readTable(os.path.join(d, "peaks.dat"))
        peaks = {label: (t, z, F) for label, t, z, F in zip(
            p.column("label"), p.column("time", finite=True),
            p.column("depth", finite=True), p.column("force", finite=True))}
    except (postProcessing.ColumnFileError, resultDigest.DigestError) as err:
        raise IndentationPlotError(str(err))
    return rows, peaks


def forceDepthAxes(ax, rows, stage, **kw):
    """Force [nN] against depth [um] of one stage's rows on ax (the
    cycles of a rate start from the preceding hold's depth)."""
    z = [r[1]*1e6 for r in rows if r[3] == stage]
    F = [r[2]*1e9 for r in rows if r[3] == stage]
    ax.plot(z, F, "-", **kw)
    ax.set_title(f"{stage}: {RATES[stage]}")
    ax.set_xlabel("indenter depth [um]")
    ax.set_ylabel("force [nN]")
    ax.grid(True)


def forceDepth(case, rows, out):
    """force-depth per rate (Figs. 4-6) and force-time to out (PNG)."""
    fig, ax = plt.subplots(1, 4, figsize=(17, 4))
    for k, stage in enumerate(["C1", "C2", "C3"]):
        forceDepthAxes(ax[k], rows, stage)
    ax[3].plot([r[0] for r in rows], [r[2]*1e9 for r in rows], "-")
    ax[3].set_xlabel("time [s]")
    ax[3].set_ylabel("force [nN]")
    ax[3].set_xscale("symlog", linthresh=30)
    ax[3].grid(True)
    fig.suptitle(os.path.basename(os.path.abspath(case)))
    fig.tight_layout()
    script.saveFigure(fig, out, dpi=110)
    plt.close(fig)


class Fields:
    """The solid at one write: X reference coordinates [m], u displacement
    [m], conn, region (index per element), names (region index -> name),
    p pressure [Pa], vm von Mises [Pa], dT temperature rise [K], t [s]."""


def regionNames(case, dim):
    """Region index -> name: the physical groups of dimension dim of
    <case>/constant/cell.msh (the mesh the solver read)."""
    try:
        return msh.physicalNames(os.path.join(case, "constant", "cell.msh"),
                                 dim)
    except msh.MshError as err:
        raise IndentationPlotError(str(err))


def fields(case, time, h5=None, tolerance=1e-6):
    """Fields at the write of solid.h5 (default postProcessing/indentation/
    solid.h5) at time [s]; an error when no write lies within
    tolerance*max(1, time) of it (tolerance None: the nearest write)."""
    h5 = h5 or os.path.join(case, "postProcessing", "indentation", "solid.h5")
    f = Fields()
    try:
        with SolidResults(h5) as r:
            k = r.nearest(time)
            f.t = float(r.time(k))
            if tolerance is not None and \
                    abs(f.t - time) > tolerance*max(1, abs(time)):
                raise IndentationPlotError(
                    "%s: no write at t = %g s (nearest %g s)"
                    % (h5, time, f.t))
            f.X = r.mesh("coordinates")
            f.conn = r.mesh("connectivity")
            f.region = r.mesh("region")
            f.u = r.field(k, "displacement")
            f.p = r.field(k, "pressure")
            f.vm = r.field(k, "vonMises")
            f.dT = r.field(k, "temperatureRise")
    except (OSError, KeyError, SolidResultsError) as err:
        raise IndentationPlotError("%s: %s" % (h5, err))
    f.names = regionNames(case, 2 if f.conn.shape[1] == 4 else 3)
    return f


def regionOutlines(conn, region):
    """{region: [(a, b)]} the edges of a quad mesh used by one element of
    the region only (its outline)."""
    out = {}
    for r in np.unique(region):
        edges = {}
        for c in conn[region == r]:
            for a, b in zip(c, np.roll(c, -1)):
                e = (min(a, b), max(a, b))
                edges[e] = edges.get(e, 0) + 1
        out[r] = [e for e, n in edges.items() if n == 1]
    return out


def fieldsFigure(f, out, title, dpi=130):
    """The r-z section (deformed) coloured by pressure and von Mises [Pa],
    region outlines in white, to out (PNG); like the paper's Figs. 7-8."""
    x = (f.X + f.u)[:, :2]*1e6
    polys = [x[c] for c in f.conn]
    outlines = regionOutlines(f.conn, f.region)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, v, name in zip(axes, (f.p, f.vm),
                           ("pressure [Pa]", "von Mises [Pa]")):
        pc = PolyCollection(polys, array=v, cmap="viridis",
                            edgecolors="none")
        ax.add_collection(pc)
        for edges in outlines.values():
            for a, b in edges:
                ax.plot(x[[a, b], 0], x[[a, b], 1], "w-", lw=0.4)
        ax.set_aspect("equal")
        ax.autoscale_view()
        ax.set_xlabel("r [um]")
        ax.set_ylabel("z [um]")
        ax.set_title("%s %s" % (name, title))
        fig.colorbar(pc, ax=ax, shrink=0.8)
    fig.tight_layout()
    script.saveFigure(fig, out, dpi=dpi)
    plt.close(fig)


def regionExtremes(f):
    """[(name, p min, p max, von Mises max)] per region [Pa]."""
    out = []
    for r in np.unique(f.region):
        m = f.region == r
        n = f.names[r] if r < len(f.names) else "region %d" % r
        out.append((n, f.p[m].min(), f.p[m].max(), f.vm[m].max()))
    return out
