"""The solid's results file solid.h5 (written by the solid library's HDF5
writer; solid.xmf beside it describes the same datasets to ParaView).

    mesh/coordinates   [nNodes, 3] reference positions [m]
    mesh/connectivity  [nElements, nodes per element] (4: r-z quads,
                       8: hexahedra)
    mesh/region        [nElements] region index
    steps/<k>          one write, attribute "time" [s]; element fields
                       (pressure [Pa], vonMises [Pa], J [-], ...) and nodal
                       fields (displacement [m], velocity [m/s])
"""

import h5py
import numpy as np

from . import options, resultDigest


class SolidResultsError(Exception):
    """A dataset of solid.h5 whose values are not what was written; the
    message names the file and the dataset."""




def digest64(values):
    """The solid library's digest of a dataset's values (src/solid/io/
    Hdf5Group.C): FNV-1a 64 over the bytes of each value as a double, in
    order, then its rows and columns as two 64-bit integers."""
    v = np.asarray(values)
    rows = v.shape[0] if v.ndim > 0 else 1
    cols = v.shape[1] if v.ndim > 1 else 1
    data = np.ascontiguousarray(v, dtype="<f8").tobytes() + \
        np.array([rows, cols], dtype="<u8").tobytes()
    # the project's one FNV-1a loop on the Python side (resultDigest.add,
    # as fileDigest::add on the C++ side)
    return resultDigest.add(resultDigest.BASIS, data)


class SolidResults:
    """solid.h5 opened for reading; use as a context manager."""

    def __init__(self, path):
        self.path = path
        # no regular file (a directory, a FIFO): named before HDF5 opens
        # it (adv53 u12: HDF5's "errno = 21, Is a directory")
        refusal = options.readRefusal(path, 0, "results file")
        if refusal:
            raise SolidResultsError(refusal)
        try:
            self.file = h5py.File(path, "r")
        except OSError as err:
            # a reader's error naming the file (adv51 n05: an OSError
            # without a file name, a traceback in plotBlast.py)
            raise SolidResultsError("%s: cannot open (%s)" % (path, err))
        self._steps = self.file["steps"]

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.file.close()

    def _read(self, key):
        """The values of dataset key, checked against their digest64 (if
        the file has one: files of earlier builds have none). HDF5's
        Fletcher-32 cannot see a 16-bit word 0x0000 turned into 0xffff
        (adv33 o13: a NaN displacement plotted, exit 0, while solidToFoam
        refused the file)."""
        d = self.file[key]
        try:
            v = d[()]
        except OSError as err:
            # HDF5's own checksum (Fletcher-32) or a damaged chunk: its
            # bare "Can't read data (data error detected by Fletcher32
            # checksum)" named neither the file nor the dataset (adv42 g21)
            raise SolidResultsError(
                "%s: dataset /%s cannot be read: %s (the file is damaged)"
                % (self.path, key, err))
        stored = d.attrs.get("digest64")
        if stored is not None and np.size(v) and \
                digest64(v) != int(stored):
            raise SolidResultsError(
                "%s: dataset /%s: its values do not match their digest "
                "digest64 (the file is damaged)" % (self.path, key))
        return v

    def mesh(self, name):
        """mesh/<name>: coordinates, connectivity or region."""
        return self._read("mesh/" + name)

    def steps(self):
        """The write keys in the order they were written."""
        return sorted(self._steps, key=int)

    def time(self, step):
        """Time of a write [s]."""
        return self._steps[step].attrs["time"]

    def times(self):
        """Times of every write [s], in the order they were written."""
        return [self.time(k) for k in self.steps()]

    def nearest(self, time):
        """Key of the write nearest to time [s] (the first one of a tie, in
        the order of the file's keys)."""
        return min(self._steps, key=lambda k: abs(self.time(k) - time))

    def field(self, step, name):
        """A field of one write."""
        return self._read("steps/%s/%s" % (step, name))
