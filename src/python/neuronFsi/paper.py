"""The paper this project reproduces (Jerusalem A, Dao M. "Continuum
modeling of a neuronal cell under blast loading", Acta Biomaterialia 2012;
the seed text): the numbers it prints, and what compares ours with them
(applications/utilities/paperFigures, tutorials/paper).

The paper's figures are pictures; where its text or tables give a number
it is here, with where it stands. A number quoted with "~" (or as it is
printed) is compared with the interval of the digits it is printed with
(quotedBar): "~300 Pa" is 250-350 Pa, "0.1" 0.05-0.15, "11.5" 11.45-11.55.

SI units unless a name says otherwise (the Table 3 forces are in nN, as
the paper prints them: its "mN" are nN).
"""

import numpy as np

# Table 3: the validation cell (14.2 x 7.6 um), maximum forces of the nine
# cycles [nN]; sec. 3.3: "always within 17 % of the experimental value,
# with an overall average error of 8.4 %"
TABLE3_LABELS = ["C%d,%s" % (a, b) for a in (1, 2, 3)
                 for b in ("i", "ii", "iii")]
TABLE3_EXP_TEXT = ["11.5", "10.8", "10.3", "5", "4.9", "4.8", "3", "3", "3"]
TABLE3_EXP = [float(x) for x in TABLE3_EXP_TEXT]
TABLE3_SIM = [11.5, 11.0, 10.2, 5.3, 4.6, 4.3, 2.5, 2.5, 2.5]
TABLE3_MAX_ERROR = 0.17
TABLE3_MEAN_ERROR_TEXT = "8.4"   # [%]

# sec. 3.1: the average cell's force at the end of the hold B and on the
# plateau E [nN]
F_B, F_E = 0.3, 1.67

# Table 1: stage, load ("+" load, "-" unload, "0" plateau), rate [um/s]
TABLE1 = [("A", "+", 0.3), ("B", "0", 0.0), ("C1", "+-", 10.0),
          ("C2", "+-", 1.0), ("C3", "+-", 0.1), ("D", "+", 10.0),
          ("E", "0", 0.0)]
TABLE1_HOLDS = {"B": 15.0, "E": 120.0}         # sec. 2.2.1 [s]
CYCLE_DEPTH = 2e-6                             # delta0 -> delta0 + 2 um [m]

# Table 2 [Pa, 1/Pa, s], and the text's values where they differ
# (sec. 3.1 eq. 10, sec. 3.2: eta1 = mu1 tau1)
TABLE2 = {
    "membrane": {"C10": 166.67, "d0": 0.0, "mu1": 13.89, "tau1": 3000.0},
    "cytoplasm": {"C10": 1.67, "d0": 0.0, "mu1": 107.78},
    "nucleus": {"C10": 13.33, "d0": 0.0, "mu1": 862.22, "tau1": 0.5},
}
TEXT_PARAMETERS = {
    "nucleus": {"C10": 6.67, "mu1": 4*107.78, "eta1": 431.11},
    "cytoplasm": {"C10": 1.66, "eta1": 1.08},
    "membrane": {"eta1": 41.67e3},
}
DELTA0_AVERAGE = 1.41e-6          # sec. 3.1 [m]
DELTA0_VALIDATION = 0.84e-6       # sec. 3.3 ("0.84 nm", read as um) [m]

# sec. 2.2.1 and Fig. 2: the average cell [m]
GEOMETRY = {"cell diameter": 16.8e-6, "cell height": 7.9e-6,
            "nucleus diameter": 11.65e-6, "nucleus height": 5.48e-6,
            "membrane thickness": 200e-9}
GEOMETRY_TEXT = {"cell diameter": "16.8", "cell height": "7.9",
                 "nucleus diameter": "11.65", "nucleus height": "5.48",
                 "membrane thickness": "200"}
BEAD_DIAMETER = 45e-6
VALIDATION_CELL = {"cell diameter": 14.2e-6, "cell height": 7.6e-6}

# sec. 2.2.2, 4: the blast scene
BOX = 100e-6                      # water cube edge [m]
OVERPRESSURE = 50e6               # [Pa]
DURATION = 5e-9                   # positive phase [s]
END_TIME = 150e-9                 # [s]

# sec. 4.2, Figs. 7-9
INDENTATION_TIME = 26.88          # Figs. 7-8, "the first indentation peak" [s]
BLAST_TIME = 65.5e-9              # Figs. 7-9 [s]
QUOTED = {
    # name: (value as printed, SI factor, unit, where)
    "jump membrane-cytoplasm": ("300", 1.0, "Pa", "sec. 4.2: the "
                                "indentation pressure jumps by ~300 Pa "
                                "across cortex-cytoplasm (Fig. 7)"),
    "jump cytoplasm-nucleus": ("30", 1.0, "Pa", "sec. 4.2: ~30 Pa across "
                               "cytoplasm-nucleus (Fig. 7)"),
    "temperature rise": ("0.1", 1.0, "K", "sec. 4.2, Fig. 9: ~0.1 C"),
    "maximum compression": ("70", 1e-9, "s", "sec. 4.2: maximum "
                            "compression is reached at 70 ns"),
}
VON_MISES_RANGE = (10.0, 100.0)   # sec. 4.2, Fig. 8: maxima ~10-100 Pa, both
                                  # scenes [Pa]

# Fig. 10 (sec. 5): 5, 10, 15 ns; "the von Mises stress ... increase[s]
# proportionally with the duration (doubling and tripling ...)"; higher
# pressure, strain and strain rate with the duration, the strain rate
# "moderately"
FIG10_DURATIONS = (5e-9, 10e-9, 15e-9)
FIG10_VON_MISES_RATIO = (1.0, 2.0, 3.0)
FIG10_HEIGHT_FRACTION = 0.75


def quotedBar(text):
    """(lo, hi) of a number as printed: +- half a unit of its last
    significant digit (trailing zeros of a whole number are not
    significant: "300" -> (250, 350), "30" -> (25, 35), "0.1" ->
    (0.05, 0.15), "11.5" -> (11.45, 11.55), "5" -> (4.5, 5.5))."""
    s = text.strip()
    v = float(s)
    if "." in s:
        unit = 10.0**-len(s.split(".")[1])
    else:
        digits = s.lstrip("+-")
        unit = 10.0**(len(digits) - len(digits.rstrip("0"))) \
            if digits.rstrip("0") else 1.0
    return v - unit/2, v + unit/2


def quoted(name):
    """(value, lo, hi) [SI] of a QUOTED number."""
    text, scale, unit, where = QUOTED[name]
    lo, hi = quotedBar(text)
    return float(text)*scale, lo*scale, hi*scale


# the element sides of a mesh by nodes per element: r-z quads (edges) or
# hexahedra (faces, gmsh/VTK order)
_SIDES = {4: ((0, 1), (1, 2), (2, 3), (3, 0)),
          8: ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5),
              (2, 3, 7, 6), (3, 0, 4, 7))}
OUTER_TO_INNER = ("membrane", "cytoplasm", "nucleus")


def _sides(conn):
    if conn.shape[1] not in _SIDES:
        raise ValueError("elements of %d nodes (valid: 4, r-z quads; 8, "
                         "hexahedra)" % conn.shape[1])
    out = {}                      # sorted side nodes -> [elements]
    for e, c in enumerate(conn):
        for s in _SIDES[conn.shape[1]]:
            out.setdefault(tuple(sorted(c[list(s)])), []).append(e)
    return out


def interfaceJumps(X, conn, region, p, names):
    """The element pressure differences across each region interface:
    {"<outer>-<inner>": (jump [Pa], midpoint [m])} with one row per shared
    element side, jump = p(outer element) - p(inner element), outer and
    inner in the order membrane, cytoplasm, nucleus (other names after,
    alphabetically). X the (current or reference) nodal coordinates."""
    rank = {n: (OUTER_TO_INNER.index(n) if n in OUTER_TO_INNER else
                len(OUTER_TO_INNER), n) for n in names}
    rows = {}
    for side, els in _sides(conn).items():
        if len(els) != 2:
            continue
        a, b = els
        na, nb = names[region[a]], names[region[b]]
        if na == nb:
            continue
        if rank[na] > rank[nb]:
            a, b, na, nb = b, a, nb, na
        rows.setdefault("%s-%s" % (na, nb), []).append(
            (p[a] - p[b], X[list(side)].mean(axis=0)))
    return {k: (np.array([j for j, x in v]), np.array([x for j, x in v]))
            for k, v in rows.items()}


def relativeJumps(conn, region, p, names):
    """{"<outer>-<inner>": r} of each region interface: the median
    |pressure jump| across its element sides over the median |pressure| of
    the elements on its two sides. Small (a few %): the interface carries
    the pressure on, as within a region; of order 1: the regions carry
    different pressures."""
    rows = {}
    for side, els in _sides(conn).items():
        if len(els) != 2 or region[els[0]] == region[els[1]]:
            continue
        rows.setdefault(tuple(sorted((region[els[0]], region[els[1]]))),
                        []).append(els)
    rank = {n: (OUTER_TO_INNER.index(n) if n in OUTER_TO_INNER else
                len(OUTER_TO_INNER), n) for n in names}
    out = {}
    for (ra, rb), pairs in rows.items():
        na, nb = sorted((names[ra], names[rb]), key=lambda n: rank[n])
        pairs = np.array(pairs)
        jump = np.abs(p[pairs[:, 0]] - p[pairs[:, 1]])
        level = np.abs(p[np.unique(pairs)])
        out["%s-%s" % (na, nb)] = float(np.median(jump)/np.median(level))
    return out


def interfaceElements(conn, region):
    """Mask of the elements with a node on another region's element."""
    nodeRegions = {}
    for e, c in enumerate(conn):
        for n in c:
            nodeRegions.setdefault(n, set()).add(region[e])
    return np.array([any(len(nodeRegions[n]) > 1 for n in c) for c in conn])


def geometry(X, conn, region, names, axial=1):
    """The average cell's dimensions from a mesh in its reference
    configuration [m]: cell and nucleus diameter (2 x the largest distance
    from the axis) and height, and the membrane thickness on the axis (the
    cell's top minus the top of the elements that are not membrane). axial:
    the coordinate along the axis (1: r-z, 2: 3D)."""
    lateral = [k for k in range(X.shape[1]) if k != axial][:2 if axial == 2
                                                          else 1]
    r = np.sqrt((X[:, lateral]**2).sum(axis=1))
    z = X[:, axial]

    def nodes(regionNames):
        ids = [k for k, n in enumerate(names) if n in regionNames]
        return np.unique(conn[np.isin(region, ids)])
    allNodes = np.unique(conn)
    nuc = nodes(["nucleus"])
    inner = nodes(["nucleus", "cytoplasm"])
    return {"cell diameter": 2*r[allNodes].max(),
            "cell height": z[allNodes].max() - z[allNodes].min(),
            "nucleus diameter": 2*r[nuc].max(),
            "nucleus height": z[nuc].max() - z[nuc].min(),
            "membrane thickness": z[allNodes].max() - z[inner].max()}


def stageRates(rows):
    """{stage: median |d depth/d time| of its moving steps [m/s]} of the
    force.dat rows [(time, depth, force, stage)] (0 for a hold)."""
    out = {}
    prev = None
    rates = {}
    for t, z, F, stage in rows:
        if prev is not None and prev[3] == stage and t > prev[0]:
            rates.setdefault(stage, []).append(abs(z - prev[1])/(t - prev[0]))
        rates.setdefault(stage, [])
        prev = (t, z, F, stage)
    for stage, r in rates.items():
        r = np.array(r)
        moving = r[r > 1e-12]
        out[stage] = float(np.median(moving)) if len(moving) else 0.0
    return out


def relativeErrors(ours, reference):
    """|ours/reference - 1| per entry."""
    return np.abs(np.asarray(ours, float)/np.asarray(reference, float) - 1)


def interfaceSides(X, conn, region, names, iface):
    """The element sides shared by the two regions of iface
    ("<outer>-<inner>", as interfaceJumps names them) of an r-z quad mesh:
    (midpoints [n, 2] (r, z) [m], outer element [n], inner element [n])."""
    outer, _, inner = iface.partition("-")
    if conn.shape[1] != 4:
        raise ValueError("interface profiles: r-z quads only (elements of "
                         "%d nodes)" % conn.shape[1])
    mids, outs, ins = [], [], []
    for side, els in _sides(conn).items():
        if len(els) != 2:
            continue
        a, b = els
        if (names[region[a]], names[region[b]]) == (inner, outer):
            a, b = b, a
        if (names[region[a]], names[region[b]]) != (outer, inner):
            continue
        mids.append(X[list(side), :2].mean(axis=0))
        outs.append(a)
        ins.append(b)
    if not mids:
        raise ValueError("no interface %s in the mesh (regions %s)"
                         % (iface, ", ".join(names)))
    return np.array(mids), np.array(outs), np.array(ins)


def interfacePoint(mids, where):
    """The index of the interface side (midpoints [n, 2] (r, z)) at
    where: "top" the side nearest the axis above the interface's
    mid-height (the pole), "side" the side farthest from the axis (the
    equator), or a direction (r, z) from the substrate's centre (0, 0):
    the side nearest that ray (ahead of the origin)."""
    if isinstance(where, str):
        if where == "top":
            z = mids[:, 1]
            up = np.nonzero(z >= 0.5*(z.min() + z.max()))[0]
            return int(up[np.argmin(mids[up, 0])])
        if where == "side":
            return int(np.argmax(mids[:, 0]))
        raise ValueError("interface point '%s' (valid: top, side, or a "
                         "direction (r, z))" % where)
    d = np.asarray(where, float)[:2]
    d = d/np.linalg.norm(d)
    along = mids @ d
    off = np.abs(mids[:, 0]*d[1] - mids[:, 1]*d[0])
    off[along <= 0] = np.inf
    return int(np.argmin(off))


def interfaceNormalProfile(X, conn, region, names, iface, where,
                           half=1.5e-6, band=0.2e-6, fit=0.6e-6):
    """The elements along the normal of interface iface ("<outer>-<inner>")
    at the point where (interfacePoint) of an r-z quad mesh with nodes at X
    [m] (current or reference): the normal is that of the straight line
    fitted (principal axis) to the midpoints of the interface's sides
    within fit [m] of the point's side, pointing into the outer region.
    Every element whose centroid lies within band [m] of the normal line
    and within half [m] of the interface along it. Returns a dict:
    elements (sorted by s), s (signed distance along the normal [m],
    positive in the outer region), origin (r, z) [m], normal (r, z)."""
    mids, outs, ins = interfaceSides(X, conn, region, names, iface)
    k = interfacePoint(mids, where)
    o = mids[k]
    near = mids[np.linalg.norm(mids - o, axis=1) <= fit]
    if len(near) >= 2:
        c = near - near.mean(axis=0)
        t = np.linalg.svd(c, full_matrices=False)[2][0]
    else:
        raise ValueError("interface %s: fewer than two sides within %g m of "
                         "the point (r, z) = (%g, %g) m" % (iface, fit,
                                                            o[0], o[1]))
    n = np.array([-t[1], t[0]])
    cen = X[conn, :2].mean(axis=1)
    if (cen[outs[k]] - o) @ n < 0:
        n = -n
    s = (cen - o) @ n
    off = np.abs((cen - o) @ np.array([n[1], -n[0]]))
    sel = np.nonzero((np.abs(s) <= half) & (off <= band))[0]
    sel = sel[np.argsort(s[sel])]
    return {"elements": sel, "s": s[sel], "origin": o, "normal": n}
