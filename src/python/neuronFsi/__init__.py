"""neuronFsi: the readers of the project's own files, shared by the
tutorials' plot scripts, the utilities, the tests and the benchmarks, and
what the scripts share (benchmark steps, scratch copies, checks).

    postProcessing  column files with a header, stitched over restarts
    solidResults    the solid's solid.h5
    msh             gmsh ASCII meshes (2.2 and 4.1)
    foamDict        OpenFOAM dictionaries: read, set an entry in the text
    logs            the numbers still taken from solver and time -v logs
    foamField       OpenFOAM fields (ascii internal field) and point lists
    bench           what the benchmark scripts share: options, timed runs,
                    the commit a run measures, the report file
    scratch         scratch copies of a case's inputs
    checks          the ok/FAIL checks of a test script
    indenterProperties  an indentation case's protocol table replaced

etc/bashrc puts src/python on PYTHONPATH.
"""
