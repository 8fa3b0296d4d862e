"""Reader of the ASCII gmsh files our tools write and read (cellMesh's
cell.msh in format 4.1, its fluid.msh in format 2.2, the tests' gmsh
cell.msh of tests/lib/cellFallback.geo), independent of gmsh.

read(path) -> (X, groups)
    X       {node tag: array of the 3 coordinates}
    groups  {physical name: (dim, [(dim, entity, type, [node tags])])}
            (format 2.2 files have no entities: entity is the element's
            physical tag)
physicalNames(path, dim): the names of the groups of one dimension by tag.
elementCount(path, types): number of elements of the given gmsh types
(3: quadrangle, 5: hexahedron, ...), whatever their physical group.
"""
import numpy as np

from . import options


class MshError(Exception):
    """A file this reader cannot read; the message names it."""


def _sections(path):
    """{section name: its lines} of a file ("$Nodes" -> lines up to
    "$EndNodes"), and the format version."""
    refusal = options.readRefusal(path, options.MESH_LIMIT, "gmsh mesh")
    if refusal:
        raise MshError(refusal)
    try:
        with open(path) as f:
            lines = [line.strip() for line in f]
    except OSError as err:
        raise MshError("%s: %s" % (path, err.strerror))
    sections, i = {}, 0
    while i < len(lines):
        if lines[i].startswith("$") and not lines[i].startswith("$End"):
            name = lines[i]
            try:
                end = lines.index("$End" + name[1:], i)
            except ValueError:
                raise MshError("%s: %s has no $End%s" % (path, name, name[1:]))
            sections[name] = lines[i + 1:end]
            i = end
        i += 1
    if "$MeshFormat" not in sections:
        raise MshError("%s: no $MeshFormat (not a gmsh file)" % path)
    version = sections["$MeshFormat"][0].split()[0]
    if version not in ("2.2", "4.1"):
        raise MshError("%s: gmsh format %s (valid: 2.2, 4.1, ASCII)"
                       % (path, version))
    return sections, version


def _names(sections):
    names = {}          # (dim, tag) -> name
    lines = sections.get("$PhysicalNames", ["0"])
    for line in lines[1:1 + int(lines[0])]:
        d, t, name = line.split(maxsplit=2)
        names[(int(d), int(t))] = name.strip('"')
    return names


def _read41(sections):
    names = _names(sections)
    entityGroups = {}   # (dim, entity) -> [physical tags]
    lines = sections["$Entities"]
    counts = [int(x) for x in lines[0].split()]
    j = 1
    for dim in range(4):
        for _ in range(counts[dim]):
            v = lines[j].split()
            k = 4 if dim == 0 else 7
            nphys = int(v[k])
            entityGroups[(dim, int(v[0]))] = \
                [int(x) for x in v[k + 1:k + 1 + nphys]]
            j += 1
    nodes = {}
    lines = sections["$Nodes"]
    j = 1
    for _ in range(int(lines[0].split()[0])):
        n = int(lines[j].split()[3])
        tags = [int(x) for x in lines[j + 1:j + 1 + n]]
        for k, t in enumerate(tags):
            nodes[t] = [float(x) for x in lines[j + 1 + n + k].split()]
        j += 1 + 2*n
    elements = []
    lines = sections["$Elements"]
    j = 1
    for _ in range(int(lines[0].split()[0])):
        dim, ent, typ, n = (int(x) for x in lines[j].split())
        for line in lines[j + 1:j + 1 + n]:
            v = [int(x) for x in line.split()]
            elements.append((dim, ent, typ, v[1:]))
        j += 1 + n
    groups = {}
    for (dim, ent), phys in entityGroups.items():
        for p in phys:
            groups.setdefault(names[(dim, p)], (dim, []))
    for e in elements:
        for p in entityGroups.get((e[0], e[1]), []):
            groups[names[(e[0], p)]][1].append(e)
    return nodes, groups


# dimension of the element types of format 2.2 files
_DIM = {1: 1, 2: 2, 3: 2, 4: 3, 5: 3, 6: 3, 7: 3, 15: 0}


def _read22(sections):
    names = _names(sections)
    nodes = {}
    lines = sections["$Nodes"]
    for line in lines[1:1 + int(lines[0])]:
        v = line.split()
        nodes[int(v[0])] = [float(x) for x in v[1:4]]
    groups = {}
    lines = sections["$Elements"]
    for line in lines[1:1 + int(lines[0])]:
        v = [int(x) for x in line.split()]
        typ, ntags = v[1], v[2]
        dim = _DIM[typ]
        name = names.get((dim, v[3]), str(v[3])) if ntags else ""
        groups.setdefault(name, (dim, []))[1].append(
            (dim, v[3], typ, v[3 + ntags:]))
    return nodes, groups


def read(path):
    """(X, groups) of an ASCII gmsh 2.2 or 4.1 file (see the module)."""
    sections, version = _sections(path)
    nodes, groups = (_read41 if version == "4.1" else _read22)(sections)
    return {t: np.array(x) for t, x in nodes.items()}, groups


def physicalNames(path, dim):
    """Names of the physical groups of dimension dim, by tag (the order of
    the solid library's region ids)."""
    names = _names(_sections(path)[0])
    return [n for (d, t), n in sorted(names.items()) if d == dim]


def elementCount(path, types):
    """Number of elements of the given gmsh types in the file."""
    sections, version = _sections(path)
    lines = sections["$Elements"]
    n = 0
    if version == "4.1":
        j = 1
        for _ in range(int(lines[0].split()[0])):
            dim, ent, typ, num = map(int, lines[j].split())
            if typ in types:
                n += num
            j += num + 1
    else:
        for line in lines[1:1 + int(lines[0])]:
            if int(line.split()[1]) in types:
                n += 1
    return n
