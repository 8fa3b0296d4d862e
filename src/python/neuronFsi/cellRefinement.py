"""The hexahedral water refined along the cell (tutorials/blast/quarter3D
Allrun -refineCell DIST; docs/results/blast3D.md, "The water along the
cell refined").

cellMesh's hexahedral water (fluid type hex) is an O-grid around the cell
whose grid along the cell surface is the inner box's (lateralSize,
axialSize): its nearSize thins the first layer only. The water's size
along the cell is what the rest state after the pulse needs (issue 17
item 6), and refining the inner box refines all of it. OpenFOAM's own
refineHexMesh (hexRef8) splits the cells of a cellSet 2x2x2 with one
layer of split-face polyhedra around them (2:1); the set is topoSet's
surfaceToCell: the water cells whose centre lies within refineDistance of
the cellInterface patch (system/topoSetDict).

readDistance checks the entry before topoSet; checkRefinement checks the
refined mesh against the set (every set cell split in eight, the interface
faces four times as many: a cell of the first layer left out would leave
them fewer)."""

import math
import os
import re

from neuronFsi import foamDict, ranges


class RefinementError(Exception):
    """Bad input or a refinement that is not what was asked; the message
    names the file and the entry."""


def _number(d, key, where):
    v = d.get(key)
    try:
        return float(v)
    except (TypeError, ValueError):
        raise RefinementError(f"{where}: entry '{key}' = {v!r} is not a "
                              "number") from None


def innerMargin(case):
    """The O-grid's inner box minus the cell [m]: system/cellMeshDict
    fluid/hexCoeffs/innerMargin, default min(a, H)/2 as cellMesh's (a the
    cell's radius, H its height); RefinementError if the water is not
    cellMesh's hexahedra (refineHexMesh splits hexahedra only)."""
    path = os.path.join(case, "system", "cellMeshDict")
    try:
        d = foamDict.read(path)
    except (OSError, foamDict.DictError) as e:
        raise RefinementError(f"{path}: {e}") from None
    fluid = d.get("fluid", {})
    if fluid.get("type", "tetrahedra") != "hex":
        raise RefinementError(
            f"{path}: entry 'fluid/type' = {fluid.get('type', 'tetrahedra')}"
            ": the refinement along the cell (refineHexMesh) splits "
            "hexahedra; valid: hex")
    hexCoeffs = fluid.get("hexCoeffs", {})
    if "innerMargin" in hexCoeffs:
        return _number(hexCoeffs, "innerMargin", path)
    a = 0.5*_number(d, "cellDiameter", path)
    H = _number(d, "cellHeight", path)
    return 0.5*min(a, H)


def _withoutActions(text):
    """The dictionary's text without its top-level list 'actions ( ... );'
    (topoSet's dictionaries in a list, which foamDict does not read; the
    distance is an entry before it)."""
    m = re.search(r"(?m)^\s*actions\s*\(", text)
    if not m:
        return text
    depth, i = 0, m.end() - 1
    while i < len(text):
        if text[i] == "(":
            depth += 1
        elif text[i] == ")":
            depth -= 1
            if depth == 0:
                j = text.find(";", i)
                return text[:m.start()] + (text[j + 1:] if j >= 0 else "")
        i += 1
    return text[:m.start()]


def readDistance(case):
    """refineDistance of system/topoSetDict [m], checked: in (0, the
    O-grid's innerMargin] (beyond it the refinement would reach the
    tensor grid of the column, which is not what it is for, and the
    distance is a length along the first layers). RefinementError names
    the file, the entry and the valid range."""
    path = os.path.join(case, "system", "topoSetDict")
    try:
        d = foamDict.parse(_withoutActions(foamDict.fileText(path)), path,
                           os.path.dirname(path))
    except (OSError, foamDict.DictError) as e:
        raise RefinementError(f"{path}: {e}") from None
    if "refineDistance" not in d:
        raise RefinementError(f"{path}: entry 'refineDistance' is missing "
                              "(the distance from the cell [m])")
    token = d["refineDistance"]
    try:
        v = float(token)
    except (TypeError, ValueError):
        v = math.nan
    margin = innerMargin(case)
    valid = ranges.Interval(f"(0, {margin:.6g}]")
    problem = ranges.readerRangeProblem(str(token), v)
    if problem or v not in valid:
        raise RefinementError(
            f"{path}: entry 'refineDistance' = {token} m is outside the "
            f"valid range {valid} m (0 excluded: nothing refined; at most "
            "the O-grid's innerMargin of system/cellMeshDict)"
            + (f": {problem}" if problem else ""))
    return v


def interfaceFaces(boundaryPath, patch="cellInterface"):
    """nFaces of a patch in a polyMesh/boundary file (always ASCII)."""
    with open(boundaryPath) as f:
        text = f.read()
    m = re.search(r"\b%s\s*\{[^}]*?\bnFaces\s+(\d+)\s*;" % re.escape(patch),
                  text)
    if not m:
        raise RefinementError(f"{boundaryPath}: no patch {patch} with "
                              "nFaces")
    return int(m.group(1))


def _logNumbers(path, pattern, what):
    try:
        with open(path) as f:
            text = f.read()
    except OSError as e:
        raise RefinementError(f"{path}: {e} ({what})") from None
    found = re.findall(pattern, text)
    if not found:
        raise RefinementError(f"{path}: no line with {what}")
    return [int(x) for x in found[-1]] if isinstance(found[-1], tuple) \
        else [int(found[-1])]


def checkRefinement(nSet, cellsBefore, cellsAfter, facesBefore,
                    facesAfter, distance):
    """The refined mesh against the set: nSet > 0 cells (else the distance
    reaches no cell centre), each split in eight (cellsAfter = cellsBefore
    + 7 nSet), and the interface faces four times as many (every cell on
    the cell's surface refined). Returns a one-line summary;
    RefinementError otherwise."""
    if nSet <= 0:
        raise RefinementError(
            f"refineDistance {distance:.6g} m reaches no water cell centre "
            "(topoSet's set refineCell is empty): the first layer's "
            "centres lie about half the fluid's nearSize from the cell; "
            "give a larger distance")
    if cellsAfter != cellsBefore + 7*nSet:
        raise RefinementError(
            f"refineHexMesh: {cellsBefore} -> {cellsAfter} water cells, "
            f"not {cellsBefore + 7*nSet} (the {nSet} cells of refineCell "
            "each split in eight): the set was extended or not refined "
            "(hexahedra only)")
    if facesAfter != 4*facesBefore:
        raise RefinementError(
            f"refineHexMesh: {facesBefore} -> {facesAfter} faces on "
            f"cellInterface, not {4*facesBefore}: not every water cell on "
            f"the cell's surface is within refineDistance {distance:.6g} m")
    return (f"Water along the cell refined once: {nSet} cells within "
            f"{distance:.6g} m of the cell split 2x2x2, {cellsBefore} -> "
            f"{cellsAfter} water cells, cellInterface {facesBefore} -> "
            f"{facesAfter} faces")


def checkCase(case, facesBefore):
    """checkRefinement from a case's logs (log.topoSet, log.refineHexMesh)
    and its polyMesh/boundary, facesBefore the interface's faces before
    refineHexMesh."""
    nSet, = _logNumbers(os.path.join(case, "log.topoSet"),
                        r"cellSet refineCell now size (\d+)",
                        "the size of the cellSet refineCell")
    before, after = _logNumbers(
        os.path.join(case, "log.refineHexMesh"),
        r"Refined from (\d+) to (\d+) cells", "'Refined from N to M cells'")
    facesAfter = interfaceFaces(os.path.join(case, "constant", "polyMesh",
                                             "boundary"))
    return checkRefinement(nSet, before, after, facesBefore, facesAfter,
                           readDistance(case))
