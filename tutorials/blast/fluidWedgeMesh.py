#!/usr/bin/python3
"""Write system/blockMeshDict of the axisymmetric water column around the
cell: r in [0, R], z in [0, Z] minus the half spheroid (r/a)^2 + (z/H)^2 <= 1
(the cell's outer surface, the same equation as cellMesh), as an OpenFOAM
wedge of angle theta about the y axis (r along x, z along y).

Five blocks in the r-z section: two around the cell (the interface curve
split at the spheroid parameter 45 deg, meeting the corner (Rb, Zb) of an
inner box), the column above the box, the ring beside it and the corner.
The interface curve is a polyLine of the exact spheroid (64 points per
block edge) so that the fluid patch points lie on it.

usage: fluidWedgeMesh.py [-h size_m] [-far size_m] [-dz size_m]
                         [-outer size_m] [-D m] [-H m] [-R m] [-Z m]
                         [-wedge deg] [-maxCells N] [-o file]
  -h      cell size at the interface [m] (default 0.5e-6)
  -far    radial cell size in the column above the inner box and at the
          inner side of the ring [m] (default 2 h)
  -dz     axial cell size above the inner box [m], where the pulse
          travels down to the cell (default: -far). The pulse is a plane
          wave there: fine cells along z keep its plateau and its fronts
          (issue 17), the radial size can stay coarse
  -outer  radial cell size at the side r = R [m] (default: -far, uniform):
          the ring and corner blocks beside the inner box are graded
          geometrically in r from -far at r = Rb to -outer at r = R. The
          incident plane wave is uniform in r, so the radial size there
          only matters for the waves the cell scatters sideways
  -Z      the column's height [m] (default 100e-6): at least one cell
          of -dz above the inner box around the cell (max(H, D/2) + 4 um,
          12.4 um for the average cell), so 12.65 um with -dz 0.25e-6
  -R      the column's radius [m] (default 50e-6): at least one radial
          cell of -far beside the inner box around the cell, so
          -R >= 12.4 um + -far for the average cell
  -D -H   the cell's diameter and height [m] (default 16.8e-6, 7.9e-6),
          positive
  -wedge  the wedge's angle [deg] (default 5), in (0, 180)
  -maxCells  largest cell count [1, 1e9] (default 1e6): the count is
          computed from the sizes before anything is written and a
          larger one refused (issue 19, class 6: -h 1e-9 hung)
  -o      the file to write (default system/blockMeshDict), in an
          existing directory
Every option is checked before anything is written (issue 19: -wedge 0,
-R inside the inner box and -o a directory were a zero-volume mesh, a
blockMesh error naming no option and a traceback).
"""
import argparse
import math
import os

import sys
try:
    from neuronFsi import script
except ImportError:
    sys.exit("fluidWedgeMesh.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import options

p = argparse.ArgumentParser(add_help=False)
p.add_argument("-h", dest="h", type=float, default=0.5e-6)
p.add_argument("-far", type=float, default=None)
p.add_argument("-dz", type=float, default=None)
p.add_argument("-outer", type=float, default=None)
p.add_argument("-D", type=float, default=16.8e-6)
p.add_argument("-H", type=float, default=7.9e-6)
p.add_argument("-R", type=float, default=50e-6)
p.add_argument("-Z", type=float, default=100e-6)
p.add_argument("-wedge", type=float, default=5.0)
p.add_argument("-maxCells", type=float, default=1e6)
p.add_argument("-o", default="system/blockMeshDict")
args = options.parse(p)     # a negative value is a value (-far -1e-6)

a, H, R, Z, h = args.D/2, args.H, args.R, args.Z, args.h
far = 2*h if args.far is None else args.far
dz = far if args.dz is None else args.dz
outer = far if args.outer is None else args.outer
for name, v in (("-h", h), ("-far", far), ("-dz", dz), ("-outer", outer),
                ("-D", args.D), ("-H", H)):
    if not (v > 0 and math.isfinite(v)):
        p.error("%s %g m: must be positive and finite" % (name, v))
if not 0 < args.wedge < 180:
    p.error("-wedge %g deg is outside the valid range (0, 180) deg"
            % args.wedge)
outDir = os.path.dirname(args.o) or "."
kind = options.notARegularFile(args.o)
if kind and kind != "a directory":
    # writing into a FIFO blocks until a reader comes
    p.error("-o %s is %s, not a file: give the file to write" % (args.o, kind))
if os.path.isdir(args.o) or not os.path.isdir(outDir):
    p.error("-o %s: %s" % (args.o, "is a directory: give the file to write"
            if os.path.isdir(args.o) else "no directory %s to write it in"
            % outDir))
if outer < far:
    p.error("-outer %g m: must be at least -far (%g m)" % (outer, far))
if not 1 <= args.maxCells <= 1e9:
    p.error("-maxCells %g is outside the valid range [1, 1e9]"
            % args.maxCells)
# a count: a whole number (adv51 n05: 1.5 was quoted "more than -maxCells
# 1" when a mesh of 2 cells was refused)
if args.maxCells != math.floor(args.maxCells):
    p.error("-maxCells %r is not a whole number: the largest cell count, "
            "a whole number in [1, 1e9]" % args.maxCells)
Rb = Zb = max(a, H) + 4e-6      # inner box around the cell [m]
# the column above the box: at least one axial cell of -dz (a shorter one
# would be a thinner cell, setting a smaller time step); a scene shortened
# by a planeWaveInflow top (Allrun -inflow) ends there at the lowest
if not (math.isfinite(Z) and Z >= Zb + dz*(1 - 1e-9)):
    p.error("-Z %g m: the water column must reach one axial cell (-dz %g m%s) "
            "above the inner box around the cell, whose top is at %g m "
            "(max(-H, -D/2) + 4 um): valid range -Z >= %g m"
            % (Z, dz, "" if args.dz is not None else
               ", -far by default" if args.far is not None else
               ", 2 -h by default: -h %g m" % h, Zb, Zb + dz))
# the ring beside the box: at least one radial cell of -far (was: -R
# inside the box wrote an inside-out block that blockMesh refused)
if not (math.isfinite(R) and R >= Rb + far*(1 - 1e-9)):
    # -far named as given or as derived from -h (adv33 fw09: only -h was
    # given, and the message named a -far the user never wrote)
    p.error("-R %g m: the water column must reach one radial cell (-far %g "
            "m%s) beside the inner box around the cell, whose side is at %g m "
            "(max(-H, -D/2) + 4 um): valid range -R >= %g m, or a smaller "
            "-far%s"
            % (R, far, "" if args.far is not None else
               ", 2 -h by default: -h %g m" % h, Rb, Rb + far,
               "" if args.far is not None else " or -h"))
alpha = math.radians(args.wedge)/2
phiP = math.radians(45.0)


def ell(phi):
    return (a*math.sin(phi), H*math.cos(phi))


def n(length, size):
    return max(1, int(round(length/size)))


P = ell(phiP)
# r-z vertices
rz = [
    (0.0, H),       # 0 cell top (axis)
    P,              # 1 cell surface at 45 deg
    (Rb, Zb),       # 2 inner box corner
    (0.0, Zb),      # 3 axis, top of the inner box
    (a, 0.0),       # 4 cell edge on the substrate
    (Rb, 0.0),      # 5
    (Rb, Z),        # 6
    (0.0, Z),       # 7
    (R, 0.0),       # 8
    (R, Zb),        # 9
    (R, Z),         # 10
]


def arcLength(phi0, phi1, m=2000):
    s = 0.0
    for i in range(m):
        x0, y0 = ell(phi0 + (phi1 - phi0)*i/m)
        x1, y1 = ell(phi0 + (phi1 - phi0)*(i + 1)/m)
        s += math.hypot(x1 - x0, y1 - y0)
    return s


# Cell counts: along the interface arcs, across the inner ring, far parts
# (the box sides get the arcs' counts: cells of about 2 h there; the
# shortest cell-to-box distance gets h, so that no cell is thinner than h)
n1 = n(arcLength(0, phiP), h)                     # arc 0-1 and box top
n2 = n(arcLength(phiP, math.pi/2), h)             # arc 1-4 and box side
nr = n(min(Zb - H, Rb - a), h)                    # from the cell outwards
nTop = n(Z - Zb, dz)


def graded(length, first, last):
    """Cells and blockMesh expansion ratio (last/first cell) of a
    geometric progression over length from about first to about last"""
    if last <= first*(1 + 1e-12):
        return n(length, first), 1.0
    best = None
    for m in range(2, n(length, first) + 1):
        q = (last/first)**(1.0/(m - 1))
        d0 = length*(q - 1)/(q**m - 1)          # first cell of m cells
        if best is None or abs(d0 - first) < abs(best[1] - first):
            best = (m, d0)
    return best[0], last/first


def tooMany(cells, atLeast):
    if cells > args.maxCells:
        p.error("the wedge water would have %s%d cells, more than -maxCells "
                "%d (coarser -h, -far, -dz or -outer, or a larger "
                "-maxCells); nothing was written"
                % ("at least " if atLeast else "", cells,
                   int(args.maxCells)))


# The count before the grading's search, which takes as long as the ring
# has cells of size -far: its ring and corner have at least (R - Rb)/outer
# cells across
tooMany(n1*nr + n2*nr + n1*nTop + n(R - Rb, outer)*(n2 + nTop), True)
nOut, gOut = graded(R - Rb, far, outer)


def side(v, s):
    """3D point of r-z vertex v on wedge side s (-1 or +1)"""
    r, z = v
    return (r*math.cos(alpha), z, s*r*math.sin(alpha))


# Vertex list: each r-z vertex on both sides; on the axis (r = 0) one point
verts, index = [], {}
for i, v in enumerate(rz):
    for s in (-1, 1):
        if v[0] == 0.0 and s == 1:
            index[(i, s)] = index[(i, -1)]
            continue
        index[(i, s)] = len(verts)
        verts.append(side(v, s))


tooMany(n1*nr + n2*nr + n1*nTop + nOut*(n2 + nTop), False)


def hexv(quad):
    return [index[(q, -1)] for q in quad] + [index[(q, 1)] for q in quad]


# (hex, counts, expansion ratio along its first direction: r in the ring
# and corner blocks)
blocks = [
    (hexv([0, 1, 2, 3]), (n1, nr), 1.0),
    (hexv([1, 4, 5, 2]), (n2, nr), 1.0),
    (hexv([3, 2, 6, 7]), (n1, nTop), 1.0),
    (hexv([5, 8, 9, 2]), (nOut, n2), gOut),
    (hexv([2, 9, 10, 6]), (nOut, nTop), gOut),
]


def fmt(p):
    return "(%.10e %.10e %.10e)" % p


def polyLine(i0, i1, phi0, phi1, s, m=64):
    pts = [side(ell(phi0 + (phi1 - phi0)*k/m), s) for k in range(1, m)]
    return "    polyLine %d %d (%s)\n" % (
        index[(i0, s)], index[(i1, s)], " ".join(fmt(q) for q in pts))


def face(quad, s0, s1):
    """quad face between r-z vertices (q0, q1) on both sides"""
    q0, q1 = quad
    return "(%d %d %d %d)" % (index[(q0, s0)], index[(q1, s0)],
                              index[(q1, s1)], index[(q0, s1)])


out = []
out.append("""FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      blockMeshDict;
}
// Generated by tutorials/blast/fluidWedgeMesh.py (do not edit: rerun it)
// Water column r <= %g um, z <= %g um minus the cell (half spheroid
// D = %g um, H = %g um), wedge %g deg about the y axis; sizes %g/%g um,
// axial size %g um above the inner box, radial size %g um at r = R
scale 1;
""" % (R*1e6, Z*1e6, 2*a*1e6, H*1e6, args.wedge, h*1e6, far*1e6,
       dz*1e6, outer*1e6))
out.append("vertices\n(\n")
for v in verts:
    out.append("    %s\n" % fmt(v))
out.append(");\nblocks\n(\n")
for hv, (na, nb), g in blocks:
    out.append("    hex (%s) (%d %d 1) simpleGrading (%.10g 1 1)\n"
               % (" ".join(map(str, hv)), na, nb, g))
out.append(");\nedges\n(\n")
for s in (-1, 1):
    out.append(polyLine(0, 1, 0.0, phiP, s))
    out.append(polyLine(1, 4, phiP, math.pi/2, s))
out.append(");\nboundary\n(\n")
patches = {
    "interface": ("wall", [(0, 1), (1, 4)]),   # FSI: the cell's surface
    "top": ("patch", [(6, 7), (10, 6)]),       # loaded face
    "bottom": ("wall", [(4, 5), (5, 8)]),      # rigid substrate
    "outer": ("wall", [(8, 9), (9, 10)]),      # slip side (mirror state)
}
comments = {
    "interface": "FSI interface: moving wall (the cell surface)",
    "top": "applied pressure pulse",
    "bottom": "rigid substrate",
    "outer": "lateral side r = R: slip wall",
}
for name, (typ, edges) in patches.items():
    out.append("    %s\n    {\n        type %s;    // %s\n        faces\n"
               "        (\n" % (name, typ, comments[name]))
    for e in edges:
        out.append("            %s\n" % face(e, -1, 1))
    out.append("        );\n    }\n")
# wedge sides: every block's front (-) and back (+) face
for name, s in (("front", -1), ("back", 1)):
    out.append("    %s\n    {\n        type wedge;\n        faces\n        (\n"
               % name)
    for hv, _, _ in blocks:
        f = hv[:4] if s == -1 else hv[4:]
        if s == -1:
            f = [f[0], f[3], f[2], f[1]]
        out.append("            (%s)\n" % " ".join(map(str, f)))
    out.append("        );\n    }\n")
out.append("""    axis
    {
        type empty;     // collapsed to a line: no faces after blockMesh
        faces
        (
            %s
            %s
        );
    }
);
""" % (face((3, 0), -1, 1), face((7, 3), -1, 1)))
try:
    with script.writing(args.o) as f:
        f.write("".join(out))
except OSError as err:
    p.error("-o %s: cannot write it: %s" % (args.o, err.strerror))
print("blockMeshDict: %d cells (blocks %s)" % (
    sum(a*b for _, (a, b), _ in blocks), [a*b for _, (a, b), _ in blocks]))
