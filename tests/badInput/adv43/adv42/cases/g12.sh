#!/bin/bash
# g12 (class 2, VTK/ and the case's own folders): finished blast, foamToVTK by hand; the user's VTK/notes.txt, notes.md in the case folder, constant/myLimits and postProcessing/myPlots/a.png; then a restart to 3 ns and foamToVTK again, -overwrite from 0, and the case's ./Allclean: which user files are kept at each step?
. "$(dirname "$0")/../lib.sh"
blastDone; foamToVTK > log.vtk 2>&1; echo "   foamToVTK rc $?: VTK $(ls VTK | head -3 | tr '\n' ' ')"
echo "g12 vtk note" > VTK/notes.txt; echo "g12 case note" > notes.md; echo "g12 const note" > constant/myLimits; mkdir -p postProcessing/myPlots; echo "g12 png" > postProcessing/myPlots/a.png
latest; blastEnd 3e-9 1e-9; tryf "restart to 3 ns" cellBlastFoam; foamToVTK > log.vtk2 2>&1; echo "   foamToVTK again rc $?"; kept "g12 vtk note" "g12 case note" "g12 const note" "g12 png"
sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; blastEnd 2e-9 1e-9; tryf "-overwrite from 0" cellBlastFoam -overwrite; kept "g12 vtk note" "g12 case note" "g12 const note" "g12 png"
ls Allclean > /dev/null 2>&1 || cp $ROOT/tutorials/blast/axisymmetricPreview/Allclean .; tryf "./Allclean" ./Allclean; kept "g12 vtk note" "g12 case note" "g12 const note" "g12 png"
