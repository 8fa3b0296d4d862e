#!/bin/bash
# w46: solidToFoam then foamToVTK (fluid) and foamToVTK -region solid on a finished blast case: all run, and a second solidToFoam is idempotent?
. "$(dirname "$0")/../lib.sh"
blastDone; try s2f solidToFoam solid/solid.h5; try vtk foamToVTK; try vtkSolid foamToVTK -region solid; try s2f-again solidToFoam solid/solid.h5; ls VTK | tr '\n' ' '; git -C "$ROOT" status --short | head -3
