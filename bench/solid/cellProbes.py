#!/usr/bin/python3
"""The coupled preview's solid probes for bench/solid/exactTraction on a
cell mesh (issue 17 item 4; docs/results/blastPlaneWave.md, "A structured
r-z cell"; not a test).

Usage: cellProbes.py CELL.msh OUT [-override FILE] [-solidProperties FILE]
                     [-along DZ,K] [-normal D1,D2,...]

Writes OUT, the driver's -probes file (NAME REGION r z [R] per line, m):
the probes of -override (default bench/blast/ballProbes.override, conv17's
points and balls) and the Fig. 10 point of -solidProperties (default the
preview's constant/solidProperties, its interfaceProbe) placed on CELL.msh
as the coupled solver places it (src/fsi/solidDomain/solidDomain.C): at
the height heightFraction of the inner region's height (its nodes' z
range), on the interface edge (both nodes in both regions) crossing that
height farthest from the axis; three probes there as the solver writes
them: interfaceProbe (the side of 'side'), interfaceProbe.INNER and
interfaceProbe.OUTER. So the same physical point is probed on a gmsh and
on a structured mesh, each at its own polygon of the nucleus surface.

The Fig. 10 point's neighbourhood (issue 17 item 4, branch conv17 of
session 44: is its ladder's alternation its place on the polygon?):
  -along DZ,K      the interfaceProbe at the heights z0 + k DZ, k = -K..K,
                   k != 0, each on its own interface edge as above,
                   cytoplasm side: interfaceProbe.zk (k signed, e.g.
                   interfaceProbe.z-2)
  -normal D1,...   points in the cytoplasm at the normal distance D [m]
                   from the exact nucleus surface (cellMeshDict's ellipse,
                   r-z: -solidProperties's case's system/cellMeshDict
                   read by neuronFsi.foamDict) at the surface point of
                   height z0: interfaceProbe.nD (D in nm), the same
                   material point on every mesh
"""
import os
import sys

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import foamDict, msh

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def option(args, name, default):
    if name in args:
        k = args.index(name)
        if k + 1 >= len(args):
            sys.exit("cellProbes.py: %s needs a file" % name)
        value = args[k + 1]
        del args[k:k + 2]
        return value
    return default


def regionElements(groups, name):
    """[[node tags]] of the 4-node quadrilaterals of the 2D group name"""
    if name not in groups or groups[name][0] != 2:
        sys.exit("cellProbes.py: no 2D region %s in the mesh" % name)
    out = []
    for (_, _, typ, nodes) in groups[name][1]:
        if typ != 3:
            sys.exit("cellProbes.py: region %s has elements of gmsh type %d,"
                     " not quadrilaterals (an r-z cell mesh?)" % (name, typ))
        out += [nodes[k:k + 4] for k in range(0, len(nodes), 4)]
    return out


def interfacePoint(path, outer, inner, fraction):
    """(r, z) of solidDomain's interfaceProbe on the mesh path"""
    X, groups = msh.read(path)
    ei = regionElements(groups, inner)
    zs = [X[n][1] for n in {n for e in ei for n in e}]
    return interfacePointAt(path, outer, inner,
                            min(zs) + fraction*(max(zs) - min(zs)))


def interfacePointAt(path, outer, inner, z):
    """(r, z): the outer-inner interface edge crossing the height z
    farthest from the axis, at z"""
    X, groups = msh.read(path)
    eo, ei = regionElements(groups, outer), regionElements(groups, inner)
    inO = {n for e in eo for n in e}
    inI = {n for e in ei for n in e}
    best = None
    for e in ei:
        for k in range(4):
            a, b = e[k], e[(k + 1) % 4]
            if not (a in inO and a in inI and b in inO and b in inI):
                continue
            za, zb = X[a][1], X[b][1]
            if (za - z)*(zb - z) > 0 or za == zb:
                continue
            t = (z - za)/(zb - za)
            r = X[a][0] + t*(X[b][0] - X[a][0])
            if best is None or r > best[0]:
                best = (r, z)
    if best is None:
        sys.exit("cellProbes.py: no %s-%s interface edge crosses z = %g m"
                 % (outer, inner, z))
    return best


def nucleusEllipse(props):
    """(a_n, c_n, z_n) [m] of the nucleus of the case of props (its
    system/cellMeshDict; cellGeometry's definitions)"""
    case = os.path.dirname(os.path.dirname(os.path.abspath(props)))
    d = foamDict.read(os.path.join(case, "system", "cellMeshDict"))
    a = 0.5*float(d["cellDiameter"])
    H = float(d["cellHeight"])
    s = float(d.get("nucleusVolumeFraction", 1.0/3.0))**(1.0/3.0)
    if d.get("nucleusShape", "centredSpheroid") == "scaledCell":
        return s*a, s*H, 0.0
    return s*a, 0.5*s*H, 0.5*H


def normalPoint(ellipse, z, d):
    """(r, z) at the distance d outward from the ellipse's point of
    height z (r > 0)"""
    an, cn, zn = ellipse
    r0 = an*(1 - ((z - zn)/cn)**2)**0.5
    nr, nz = r0/an**2, (z - zn)/cn**2
    n = (nr*nr + nz*nz)**0.5
    return r0 + d*nr/n, z + d*nz/n


def main():
    args = sys.argv[1:]
    override = option(args, "-override",
                      os.path.join(root, "bench", "blast",
                                   "ballProbes.override"))
    props = option(args, "-solidProperties",
                   os.path.join(root, "tutorials", "blast",
                                "axisymmetricPreview", "constant",
                                "solidProperties"))
    along = option(args, "-along", None)
    normal = option(args, "-normal", None)
    if len(args) != 2:
        sys.exit(__doc__)
    mesh, out = args
    lines = ["# NAME REGION r z [R] [m] (bench/solid/cellProbes.py %s)"
             % mesh]
    for name, p in foamDict.read(override)["probes"].items():
        r, z = p["point"][0], p["point"][1]
        lines.append("%s %s %.10g %.10g %.10g"
                     % (name, p["region"], r, z, p.get("radius", 0)))
    ip = foamDict.read(props)["interfaceProbe"]
    outer, inner = ip["regions"]
    fraction = float(ip["heightFraction"])
    r, z = interfacePoint(mesh, outer, inner, fraction)
    side = outer if ip.get("side", "outer") == "outer" else inner
    for name, region in (("interfaceProbe", side),
                         ("interfaceProbe." + inner, inner),
                         ("interfaceProbe." + outer, outer)):
        lines.append("%s %s %.10g %.10g 0" % (name, region, r, z))
    if along:
        try:
            dz, K = along.split(",")
            dz, K = float(dz), int(K)
        except ValueError:
            sys.exit("cellProbes.py: -along DZ,K: a height step [m] and a "
                     "count (> 0), not '%s'" % along)
        if not (dz > 0 and K > 0):
            sys.exit("cellProbes.py: -along DZ,K needs DZ > 0 m and K > 0,"
                     " not '%s'" % along)
        for k in list(range(-K, 0)) + list(range(1, K + 1)):
            rk, zk = interfacePointAt(mesh, outer, inner, z + k*dz)
            lines.append("interfaceProbe.z%d %s %.10g %.10g 0"
                         % (k, outer, rk, zk))
    if normal:
        try:
            ds = [float(v) for v in normal.split(",")]
        except ValueError:
            sys.exit("cellProbes.py: -normal D1,D2,...: distances [m], not "
                     "'%s'" % normal)
        if not all(0 < d < 1e-6 for d in ds):
            sys.exit("cellProbes.py: -normal: every distance in (0, 1e-6) m"
                     ", not '%s'" % normal)
        ell = nucleusEllipse(props)
        for d in ds:
            rd, zd = normalPoint(ell, z, d)
            lines.append("interfaceProbe.n%d %s %.10g %.10g 0"
                         % (round(d*1e9), outer, rd, zd))
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
