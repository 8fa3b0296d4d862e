"""Minimal reader of ASCII gmsh 4.1 files (nodes, elements, physical
groups), independent of gmsh, for the cellMesh tests."""
import numpy as np


def read(path):
    with open(path) as f:
        lines = [l.strip() for l in f]
    i = 0
    names = {}          # (dim, tag) -> name
    entityGroups = {}   # (dim, entity) -> [physical tags]
    nodes = {}
    elements = []       # (dim, entity, type, [node tags])
    while i < len(lines):
        key = lines[i]
        if key == "$MeshFormat":
            assert lines[i + 1].split()[0] == "4.1", lines[i + 1]
        elif key == "$PhysicalNames":
            n = int(lines[i + 1])
            for l in lines[i + 2:i + 2 + n]:
                d, t, name = l.split(maxsplit=2)
                names[(int(d), int(t))] = name.strip('"')
        elif key == "$Entities":
            counts = [int(x) for x in lines[i + 1].split()]
            j = i + 2
            for dim in range(4):
                for _ in range(counts[dim]):
                    v = lines[j].split()
                    tag = int(v[0])
                    k = 4 if dim == 0 else 7
                    nphys = int(v[k])
                    entityGroups[(dim, tag)] = \
                        [int(x) for x in v[k + 1:k + 1 + nphys]]
                    j += 1
        elif key == "$Nodes":
            nb = int(lines[i + 1].split()[0])
            j = i + 2
            for _ in range(nb):
                n = int(lines[j].split()[3])
                tags = [int(x) for x in lines[j + 1:j + 1 + n]]
                for k, t in enumerate(tags):
                    nodes[t] = [float(x) for x in lines[j + 1 + n + k].split()]
                j += 1 + 2*n
        elif key == "$Elements":
            nb = int(lines[i + 1].split()[0])
            j = i + 2
            for _ in range(nb):
                dim, ent, typ, n = (int(x) for x in lines[j].split())
                for l in lines[j + 1:j + 1 + n]:
                    v = [int(x) for x in l.split()]
                    elements.append((dim, ent, typ, v[1:]))
                j += 1 + n
        i += 1
    groups = {}   # name -> (dim, [elements])
    for (dim, ent), phys in entityGroups.items():
        for p in phys:
            groups.setdefault(names[(dim, p)], (dim, []))
    for e in elements:
        for p in entityGroups.get((e[0], e[1]), []):
            groups[names[(e[0], p)]][1].append(e)
    X = {t: np.array(x) for t, x in nodes.items()}
    return X, groups
