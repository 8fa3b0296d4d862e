"""One structured r-z mesh of the Hertz indentation, written for both codes.

The block [0, W] x [0, H] (um) is mapped from the unit square with the
geometric grading of tests/solid/testContact.C, refined towards the first
contact point (r = 0, z = H):
    r = W g(xi),  z = H (1 - g(1 - eta)),  g(s) = expm1(beta s)/expm1(beta)
Written as
  - gmsh 2.2 ASCII (.msh) for our library: physical groups solid (quads),
    bottom, left, contact (lines);
  - CalculiX input (.inp): the same nodes and CAX4 quads (x = r, y = z),
    plus the sphere, which CalculiX cannot model as an analytical surface:
    a one-element-thick cap of very stiff linear-elastic CAX4 elements whose
    outer nodes lie on the sphere at the radii of the block's contact nodes
    and whose inner nodes are moved rigidly by the depth; frictionless
    surface-to-surface penalty contact, block = slave.
The contact face set of both codes is the top faces with r <= rContact.
"""
import math


class Geometry:
    """Sizes in um, moduli in Pa (CalculiX force unit Pa um^2 = 1e-12 N)."""

    def __init__(self, R, depth, W, H, mu, K, rContact, beta=4.0):
        self.R, self.depth, self.W, self.H = R, depth, W, H
        self.mu, self.K, self.rContact, self.beta = mu, K, rContact, beta

    def g(self, s):
        return math.expm1(self.beta*s)/math.expm1(self.beta)


def structured(geo, n):
    """Nodes [(r, z)] (id = index + 1) and quads (counter-clockwise)."""
    nodes = []
    for j in range(n + 1):
        for i in range(n + 1):
            nodes.append((geo.W*geo.g(i/n), geo.H*(1 - geo.g(1 - j/n))))
    node = lambda i, j: j*(n + 1) + i + 1
    quads = [(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1))
             for j in range(n) for i in range(n)]
    bottom = [node(i, 0) for i in range(n + 1)]
    left = [node(0, j) for j in range(n + 1)]
    # Top faces (element index, its two nodes) with r <= rContact
    top = []
    for i in range(n):
        if nodes[node(i, n) - 1][0] < geo.rContact:
            top.append((n*(n - 1) + i + 1, node(i, n), node(i + 1, n)))
    return nodes, quads, bottom, left, top


def writeGmsh(path, nodes, quads, bottom, left, top):
    groups = [(2, 1, "solid"), (1, 2, "bottom"), (1, 3, "left"),
              (1, 4, "contact")]
    lines = lambda ns: list(zip(ns[:-1], ns[1:]))
    elems = [(3, 1, q) for q in quads]
    elems += [(1, 2, l) for l in lines(bottom)]
    elems += [(1, 3, l) for l in lines(left)]
    elems += [(1, 4, (a, b)) for _, a, b in top]
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n")
        f.write(f"{len(groups)}\n")
        for dim, tag, name in groups:
            f.write(f'{dim} {tag} "{name}"\n')
        f.write(f"$EndPhysicalNames\n$Nodes\n{len(nodes)}\n")
        for k, (r, z) in enumerate(nodes):
            f.write(f"{k + 1} {r:.15g} {z:.15g} 0\n")
        f.write(f"$EndNodes\n$Elements\n{len(elems)}\n")
        for k, (typ, tag, ns) in enumerate(elems):
            f.write(f"{k + 1} {typ} 2 {tag} {tag} "
                    + " ".join(map(str, ns)) + "\n")
        f.write("$EndElements\n")


def writeCalculix(path, geo, nodes, quads, bottom, left, top, slope,
                  nSteps, element="CAX8R", printTimes=None):
    """slope: penalty of the linear pressure-overclosure law [Pa/um].

    printTimes: step times (fractions of geo.depth) at which the increments
    end exactly and the reaction is printed (*TIME POINTS); None: every
    increment.

    element CAX4 (linear, full integration: locks at K/mu = 1e3, kept to
    show it) or CAX8R (quadratic serendipity, reduced integration, the
    CalculiX choice for nearly incompressible solids): midside nodes at
    the midpoints of the same straight edges, on the arcs of the sphere.
    """
    quadratic = element.startswith("CAX8")
    coords = list(nodes)

    def addNode(x, y):
        coords.append((x, y))
        return len(coords)

    mids = {}

    def mid(a, b):
        key = (min(a, b), max(a, b))
        if key not in mids:
            (xa, ya), (xb, yb) = coords[a - 1], coords[b - 1]
            mids[key] = addNode(0.5*(xa + xb), 0.5*(ya + yb))
        return mids[key]

    def withMids(q):
        if not quadratic:
            return list(q)
        return list(q) + [mid(q[k], q[(k + 1) % 4]) for k in range(4)]

    block = [withMids(q) for q in quads]
    edgeNodes = lambda ns: ns + ([mid(a, b) for a, b in zip(ns[:-1], ns[1:])]
                                 if quadratic else [])
    bottomSet, axisSet = edgeNodes(list(bottom)), edgeNodes(list(left))

    # Sphere cap: outer nodes on the sphere at the radii of the contact
    # nodes plus two beyond (the master surface covers every slave face),
    # inner nodes t = R/10 deeper along the sphere normal; arc midpoints at
    # the mid angle
    zc = geo.H + geo.R
    radii = [nodes[a - 1][0] for _, a, _ in top] + [nodes[top[-1][2] - 1][0]]
    radii.append(2*radii[-1] - radii[-2])
    angles = [math.asin(r/geo.R) for r in radii]
    t = 0.1*geo.R
    onSphere = lambda rho, th: addNode(rho*math.sin(th),
                                       zc - rho*math.cos(th))
    outer = [onSphere(geo.R, th) for th in angles]
    inner = [onSphere(geo.R - t, th) for th in angles]
    cap, drive, axisCap = [], list(inner), [outer[0], inner[0]]
    for k in range(len(angles) - 1):
        q = [outer[k], outer[k + 1], inner[k + 1], inner[k]]
        if quadratic:
            thm = 0.5*(angles[k] + angles[k + 1])
            om, im = onSphere(geo.R, thm), onSphere(geo.R - t, thm)
            q += [om, mid(outer[k + 1], inner[k + 1]), im,
                  mid(inner[k], outer[k])]
            drive.append(im)
            if k == 0:
                axisCap.append(q[7])
        cap.append(q)
    firstCap = len(block) + 1
    E = 1e4*3*geo.mu     # 1e4 x the block's Young's modulus
    capType = "CAX8" if quadratic else "CAX4"
    out = []
    w = out.append
    w("** Hertz indentation, generated by bench/solid/calculix/hertzMesh.py")
    w("** units: um, Pa; force unit Pa um^2 = 1e-12 N; RF per 2 degrees")
    w("*NODE, NSET=NALL")
    for k, (x, y) in enumerate(coords):
        w(f"{k + 1}, {x:.15g}, {y:.15g}")

    def elements(typ, name, first, conn):
        w(f"*ELEMENT, TYPE={typ}, ELSET={name}")
        for k, q in enumerate(conn):
            w(f"{first + k}, " + ", ".join(map(str, q)))
    elements(element, "BLOCK", 1, block)
    elements(capType, "SPHERE", firstCap, cap)

    def nset(name, ids):
        w(f"*NSET, NSET={name}")
        for k in range(0, len(ids), 10):
            w(", ".join(map(str, ids[k:k + 10])))
    nset("BOTTOM", bottomSet)
    nset("AXIS", axisSet + axisCap)
    nset("DRIVE", drive)
    w("*SURFACE, NAME=SBLOCK")
    for e, _, _ in top:
        w(f"{e}, S3")
    w("*SURFACE, NAME=SSPHERE")
    for k in range(len(cap)):
        w(f"{firstCap + k}, S1")
    w("*MATERIAL, NAME=NEOHOOKE")
    # U = C10 (I1bar - 3) + (J - 1)^2/D1: mu = 2 C10, K = 2/D1
    w("*HYPERELASTIC, NEO HOOKE")
    w(f"{geo.mu/2:.10g}, {2/geo.K:.10g}")
    w("*MATERIAL, NAME=RIGID")
    w("*ELASTIC")
    w(f"{E:.10g}, 0.3")
    w("*SOLID SECTION, ELSET=BLOCK, MATERIAL=NEOHOOKE")
    w("*SOLID SECTION, ELSET=SPHERE, MATERIAL=RIGID")
    w("*SURFACE INTERACTION, NAME=FRICTIONLESS")
    w("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR")
    w(f"{slope:.10g}")
    w("*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE=SURFACE TO SURFACE")
    w("SBLOCK, SSPHERE")
    w("*BOUNDARY")
    w("BOTTOM, 1, 2, 0.")
    w("AXIS, 1, 1, 0.")
    w("DRIVE, 1, 1, 0.")
    if printTimes:
        w("*TIME POINTS, NAME=PRINTED")
        w(", ".join(f"{t:.15g}" for t in printTimes))
    w("*STEP, NLGEOM, INC=1000")
    w("*STATIC")
    w(f"{1/nSteps:.10g}, 1., 1e-6, {1/nSteps:.10g}")
    w("*BOUNDARY")
    w(f"DRIVE, 2, 2, {-geo.depth:.15g}")
    w("*NODE PRINT, NSET=DRIVE, TOTALS=ONLY"
      + (", TIME POINTS=PRINTED" if printTimes else ""))
    w("RF")
    w("*END STEP")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
