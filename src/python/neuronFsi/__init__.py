"""neuronFsi: the readers of the project's own files, shared by the
tutorials' plot scripts, the utilities, the tests and the benchmarks, and
the benchmarks' common steps.

    postProcessing  column files with a header, stitched over restarts
    solidResults    the solid's solid.h5
    msh             gmsh ASCII meshes (2.2 and 4.1)
    foamDict        OpenFOAM dictionaries: read, set an entry in the text
    logs            the numbers still taken from solver and time -v logs
    bench           what the benchmark scripts share: timed runs, the
                    commit a run measures, the report file

etc/bashrc puts src/python on PYTHONPATH.
"""
