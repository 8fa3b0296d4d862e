"""Observed order of convergence, Richardson extrapolation and the error bar
of a quantity computed on three meshes: one implementation for every
ladder script (bench/blast/run.py, transparentLadder.py, solidProbeLadder.py,
ballLadder.py, bench/solid/interfaceLadder.py, bench/solid/layer/run.py).

The procedure is the grid convergence index of Celik et al. 2008 (J. Fluids
Eng. 130, 078001, "Procedure for estimation and reporting of uncertainty due
to discretization in CFD applications"), which follows Roache 1998
(Verification and Validation in Computational Science and Engineering):

with h1 < h2 < h3 the three finest sizes (any unit: only ratios enter),
f1, f2, f3 the quantity on them and the model f = f0 + C h^p,

    e21 = f2 - f1,  e32 = f3 - f2,  r21 = h2/h1,  r32 = h3/h2,
    e32/e21 = r21^p (r32^p - 1)/(r21^p - 1)            (Celik's eq. 3)

is solved for p. Its right side grows monotonically with p from
ln(r32)/ln(r21) at p -> 0, so it has a root p > 0 exactly when e32/e21
exceeds that value; it is found by bisection in (PMIN, PMAX]. Then

    f0 = (r21^p f1 - f2)/(r21^p - 1)                   (Celik's eq. 4)
    GCI = 1.25 |e21/f1| / (r21^p - 1)                 (Celik's eq. 7)

The three kinds (Celik's section 4):
- "monotone": e21 and e32 of one sign and a root p in (PMIN, PMAX];
- "oscillatory": e21 and e32 of opposite signs: no order and no
  extrapolation; the error bar reported is half the range of the three
  values (Celik's note 4, after Roache), and Roache's conservative bar
  3 max(|e21|, |e32|)/|f1| (factor of safety 3 where the order is unknown)
  as gci;
- "divergent": one sign, but the changes do not shrink: e32/e21 at or
  below its value for p = PMIN; no order, bars as for "oscillatory";
- "undetermined": a change is exactly zero, or the changes shrink faster
  than p = PMAX (the two finest values agree to round-off, not to a
  discretisation error): no order, bars as for "oscillatory".
"""
import collections
import math

PMIN = 0.05
PMAX = 16.0

Convergence = collections.namedtuple(
    "Convergence",
    "kind h values p extrapolated gci halfRange")
Convergence.__doc__ = """The three finest levels' verdict:
kind         'monotone' | 'oscillatory' | 'divergent' | 'undetermined'
h            (h1, h2, h3), finest first
values       (f1, f2, f3), finest first
p            observed order (None unless monotone)
extrapolated f0, the Richardson value (None unless monotone)
gci          relative error bar of f1: Celik's GCI if monotone, else
             3 max(|e21|, |e32|)/|f1| (Roache's factor of safety 3)
halfRange    0.5 (max - min) of the three values (absolute)"""


def _ratio(h1, h2, h3, p):
    """(h3^p - h2^p)/(h2^p - h1^p), the model's e32/e21"""
    return (h3**p - h2**p)/(h2**p - h1**p)


def threeLevel(h, f):
    """The verdict (a Convergence) of the three finest of the levels with
    sizes h and values f (sequences of equal length >= 3, in any order;
    sizes positive and distinct). ValueError for anything else."""
    h = [float(x) for x in h]
    f = [float(x) for x in f]
    if len(h) != len(f) or len(h) < 3:
        raise ValueError("convergence.threeLevel: %d sizes and %d values; "
                         "at least three of each, as many sizes as values"
                         % (len(h), len(f)))
    if not all(math.isfinite(x) and x > 0 for x in h):
        raise ValueError("convergence.threeLevel: sizes %s: each must be a "
                         "positive finite number" % (h,))
    if not all(math.isfinite(x) for x in f):
        raise ValueError("convergence.threeLevel: values %s: each must be "
                         "finite" % (f,))
    (h1, f1), (h2, f2), (h3, f3) = sorted(zip(h, f))[:3]
    if not h1 < h2 < h3:
        raise ValueError("convergence.threeLevel: sizes %s: the three finest "
                         "must be distinct" % ((h1, h2, h3),))
    e21, e32 = f2 - f1, f3 - f2
    halfRange = 0.5*(max(f1, f2, f3) - min(f1, f2, f3))
    bar = 3*max(abs(e21), abs(e32))/abs(f1) if f1 != 0 else math.inf

    def verdict(kind, p=None, f0=None, gci=bar):
        return Convergence(kind, (h1, h2, h3), (f1, f2, f3), p, f0, gci,
                           halfRange)

    if e21 == 0 or e32 == 0:
        return verdict("undetermined")
    if (e21 > 0) != (e32 > 0):
        return verdict("oscillatory")
    target = e32/e21
    lo, hi = PMIN, PMAX
    if target <= _ratio(h1, h2, h3, lo):
        return verdict("divergent")
    if target > _ratio(h1, h2, h3, hi):
        return verdict("undetermined")
    for _ in range(200):
        mid = 0.5*(lo + hi)
        if _ratio(h1, h2, h3, mid) < target:
            lo = mid
        else:
            hi = mid
        if hi - lo <= 1e-15*hi:
            break
    p = 0.5*(lo + hi)
    r = (h2/h1)**p
    f0 = (r*f1 - f2)/(r - 1)
    gci = 1.25*abs(e21/f1)/(r - 1) if f1 != 0 else math.inf
    return verdict("monotone", p, f0, gci)
