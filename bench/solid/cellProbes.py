#!/usr/bin/python3
"""The coupled preview's solid probes for bench/solid/exactTraction on a
cell mesh (issue 17 item 4; docs/results/blastPlaneWave.md, "A structured
r-z cell"; not a test).

Usage: cellProbes.py CELL.msh OUT [-override FILE] [-solidProperties FILE]

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
"""
import os
import sys

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
    eo, ei = regionElements(groups, outer), regionElements(groups, inner)
    inO = {n for e in eo for n in e}
    inI = {n for e in ei for n in e}
    zs = [X[n][1] for n in inI]
    z = min(zs) + fraction*(max(zs) - min(zs))
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


def main():
    args = sys.argv[1:]
    override = option(args, "-override",
                      os.path.join(root, "bench", "blast",
                                   "ballProbes.override"))
    props = option(args, "-solidProperties",
                   os.path.join(root, "tutorials", "blast",
                                "axisymmetricPreview", "constant",
                                "solidProperties"))
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
    r, z = interfacePoint(mesh, outer, inner, float(ip["heightFraction"]))
    side = outer if ip.get("side", "outer") == "outer" else inner
    for name, region in (("interfaceProbe", side),
                         ("interfaceProbe." + inner, inner),
                         ("interfaceProbe." + outer, outer)):
        lines.append("%s %s %.10g %.10g 0" % (name, region, r, z))
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
