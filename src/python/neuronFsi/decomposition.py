"""Domain decomposition of the blast scenes into sectors about the cell's
axis (decomposePar method manual).

The work of a coupled step is not the fluid cells alone: the band of
cells that moves with the interface (interfaceMotion, bandMeshMotion), the
interface faces and the probes all lie around the cell, and OpenFOAM's
simple or scotch methods split by cell count only. In the 3D quarter,
simple (2 1 1) put the cell and nearly all of the band (6,005 of 6,407
moving points) on rank 0. Equal angular sectors about the axis through
the cell split the cell, its band and the water alike; for two ranks in
the quarter (x, y >= 0) the two halves x > y and x < y are mirror images
of each other when the mesh is (cellMesh's even O-grid and tensor grid
are).

The cell centres come from OpenFOAM (postProcess -func writeCellCentres,
0/C); the labels go to constant/cellDecomposition, the dataFile of
decomposePar's manual method."""

import os

import numpy as np

from neuronFsi import foamField


class DecompositionError(Exception):
    """Inputs that cannot be decomposed; the message names them."""


def sectors(centres, n, origin=(0.0, 0.0, 0.0), axis=(0.0, 0.0, 1.0)):
    """Processor of each cell: n sectors about the axis through origin
    along axis, each with m/n of the m cells (to one), in the order of
    the angle about the axis (the quarter: 0 to 90 degrees; a whole box:
    -180 to 180). centres: m x 3 [m]; returns m labels in [0, n)."""
    if int(n) != n or n < 1:
        raise DecompositionError(f"number of sectors {n}: an integer >= 1 "
                                 "wanted")
    c = np.asarray(centres, float)
    if c.ndim != 2 or c.shape[1] != 3 or len(c) == 0:
        raise DecompositionError("cell centres: a non-empty m x 3 array "
                                 "wanted")
    if not np.all(np.isfinite(c)):
        raise DecompositionError("cell centres: not all finite")
    a = np.asarray(axis, float)
    if not (np.linalg.norm(a) > 0):
        raise DecompositionError(f"axis {tuple(axis)}: a non-zero vector "
                                 "wanted")
    a = a/np.linalg.norm(a)
    if n > len(c):
        raise DecompositionError(f"{n} sectors for {len(c)} cells: at most "
                                 "one rank per cell (valid range [1, "
                                 f"{len(c)}])")
    # An orthonormal frame (e1, e2, a); e1 along the coordinate axis least
    # aligned with a
    k = int(np.argmin(np.abs(a)))
    e1 = np.zeros(3)
    e1[k] = 1.0
    e1 -= (e1 @ a)*a
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(a, e1)
    r = c - np.asarray(origin, float)
    theta = np.arctan2(r @ e2, r @ e1)
    # In angular order (ties, e.g. the cells on the quarter's diagonal, by
    # cell index), n runs of equal cell count: equal sectors where the
    # mesh is symmetric, and the same number of cells per rank where it
    # is not quite (the angle -pi..pi: a whole turn is cut at -e1)
    order = np.lexsort((np.arange(len(c)), theta))
    labels = np.empty(len(c), int)
    labels[order] = np.arange(len(c))*n//len(c)
    return labels


def writeManual(case, labels, name="cellDecomposition"):
    """constant/<name>: the labelList decomposePar's manual method reads
    (dataFile "<name>";)."""
    labels = np.asarray(labels, int)
    path = os.path.join(case, "constant", name)
    lines = [
        "FoamFile",
        "{",
        "    version     2.0;",
        "    format      ascii;",
        "    class       labelList;",
        "    location    \"constant\";",
        f"    object      {name};",
        "}",
        "",
        str(len(labels)),
        "(",
    ]
    lines += [str(int(v)) for v in labels]
    lines += [")", ""]
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(lines))
    os.replace(tmp, path)
    return path


# the fewest cells a rank of a decomposition holds
MIN_CELLS_PER_RANK = 100


def sectorDecomposition(case, n, origin=(0.0, 0.0, 0.0),
                        axis=(0.0, 0.0, 1.0), centres="0/C"):
    """Read the cell centres (<case>/<centres>, ascii, from postProcess
    -func writeCellCentres), write constant/cellDecomposition with n
    sectors; returns the cells per processor."""
    path = os.path.join(case, centres)
    try:
        c = foamField.internalField(path)
    except (OSError, ValueError, foamField.FieldError) as err:
        # a re-run of an Allrun whose writeCellCentres step was skipped
        # (its log there) after 0/C was removed: a traceback (adv pass q46)
        raise DecompositionError(
            "the cell centres %s cannot be read (%s): write them with "
            "postProcess -func writeCellCentres -time 0 (remove its log "
            "log.postProcess to have an Allrun run it again)"
            % (path, err.strerror if isinstance(err, OSError) else err))
    if c.ndim != 2:
        raise DecompositionError(f"{os.path.join(case, centres)}: cell "
                                 "centres (a vector field) wanted")
    # a rank's share must outweigh its exchange with the others: n ranks
    # for a few cells each were accepted (adv pass q34: -np 4096)
    if len(c) < MIN_CELLS_PER_RANK*n:
        raise DecompositionError(
            "%d ranks for %d cells: fewer than %d cells per rank (valid "
            "range [1, %d] ranks for this mesh)" % (
                n, len(c), MIN_CELLS_PER_RANK,
                max(1, len(c)//MIN_CELLS_PER_RANK)))
    labels = sectors(c, n, origin, axis)
    writeManual(case, labels)
    return np.bincount(labels, minlength=n)
