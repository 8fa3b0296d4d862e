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


class SolidResults:
    """solid.h5 opened for reading; use as a context manager."""

    def __init__(self, path):
        self.path = path
        try:
            self.file = h5py.File(path, "r")
        except OSError as err:
            raise OSError("%s: cannot open (%s)" % (path, err))
        self._steps = self.file["steps"]

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.file.close()

    def mesh(self, name):
        """mesh/<name>: coordinates, connectivity or region."""
        return self.file["mesh/" + name][()]

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
        return self._steps[step][name][()]
