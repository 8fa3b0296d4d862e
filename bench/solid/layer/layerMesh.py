"""The graded r-z map of the layer indentation, shared by all three codes.

The layer [0, W] x [0, H] (um) is the image of the unit square under
    r = rOf(s),  z = H - zOf(1 - t)
with cell sizes uniform on r <= rFine and growing as
1 + ((r - rFine)/3 um)^2 beyond (gradedMap), and growing with the distance
from the top as 1 + 2 (depth/H)^2 (cells at the bottom three times those at
the top). The map is smooth, so meshes of n x m cells and 2n x 2m cells of
the same map are a refinement sequence fit for Richardson extrapolation.

structured() gives the quads in the form of bench/solid/calculix/
hertzMesh.py (nodes, quads, bottom, left, top) for hertzMesh.writeGmsh and
writeCalculix (ours and CalculiX on the same nodes); fenicsLayer.py maps
dolfin's triangulation of the unit square with mapPoints().
"""
import numpy as np


def gradedMap(s, length, fine, growth):
    """s in [0, 1] -> [0, length]: cell size 1 on [0, fine], growing as
    1 + ((x - fine)/growth)^2 beyond (the integral of 1/size inverted)."""
    x = np.linspace(0, length, 20001)
    size = 1 + np.where(x > fine, ((x - fine)/growth)**2, 0)
    t = np.concatenate([[0], np.cumsum(0.5*(1/size[1:] + 1/size[:-1])
                                        * np.diff(x))])
    return np.interp(s, t/t[-1], x)


def mapPoints(s, t, W, H, rFine):
    """Unit-square coordinates (arrays s, t) -> (r, z) [um]."""
    r = gradedMap(np.asarray(s, float), W, rFine, 3.0)
    z = H - gradedMap(1 - np.asarray(t, float), H, 0.0, H/np.sqrt(2))
    return r, z


def structured(W, H, rFine, rContact, n, m):
    """n x m quads (counter-clockwise): nodes [(r, z)] (id = index + 1),
    quads, bottom and axis node ids, and the top faces (element id, node,
    node) with r <= rContact, as hertzMesh.structured."""
    s, t = np.meshgrid(np.arange(n + 1)/n, np.arange(m + 1)/m)
    r, z = mapPoints(s.ravel(), t.ravel(), W, H, rFine)
    r[np.isclose(s.ravel(), 0)] = 0.0
    z[np.isclose(t.ravel(), 1)] = H
    nodes = list(zip(r.tolist(), z.tolist()))
    node = lambda i, j: j*(n + 1) + i + 1
    quads = [(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1))
             for j in range(m) for i in range(n)]
    bottom = [node(i, 0) for i in range(n + 1)]
    left = [node(0, j) for j in range(m + 1)]
    top = [(n*(m - 1) + i + 1, node(i, m), node(i + 1, m))
           for i in range(n) if nodes[node(i, m) - 1][0] < rContact]
    return nodes, quads, bottom, left, top
