#!/bin/bash
# z15: resources of the WATER mesh: the preview Allrun with -far 1e-9 -dz 1e-9 -h 1e-9 (about 1e10 fluid cells) and -noRun, under a 3 GB address-space limit: refused before blockMesh allocates (naming the option or the size and a limit), or blockMesh runs out of memory / runs long?
. "$(dirname "$0")/../lib.sh"
prev; ulimit -v 3000000
run 120 ./Allrun -h 1e-9 -far 1e-9 -dz 1e-9 -cell 0.5e-6 -Z 20e-6 -endTime 2e-9 -noPlots -noVTK -noRun > ../log.a 2>&1; tail -4 ../log.a | cut -c1-250; echo "   logs: $(ls log.* 2>/dev/null | tr '\n' ' ')"; [ -f log.blockMesh ] && tail -3 log.blockMesh
run 120 ./Allrun -h 0.25e-6 -far 2e-6 -dz 1e-10 -cell 0.5e-6 -Z 20e-6 -endTime 2e-9 -noPlots -noVTK -noRun > ../log.b 2>&1; tail -3 ../log.b | cut -c1-250
