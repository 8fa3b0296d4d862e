#!/bin/bash
# w83: blast Allrun options at the edges: -amplitude 50MPa, -pulse 0, -endTime -1e-9, -writeInterval 0, -cell nan, -Z 1e300, -h 0.25 (um as m)
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/c; cd $W/c; for o in "-amplitude 50MPa" "-pulse 0" "-endTime -1e-9" "-writeInterval 0" "-cell nan" "-Z 1e300" "-h 0.25"; do try "$o" ./Allrun $o -noPlots -noVTK -noRun; done; ls | tr '\n' ' '
