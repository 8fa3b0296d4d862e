#!/bin/bash
# k09 (class 2, VTK/ and the tutorial's Allrun re-run): the preview tutorial's Allrun ($PREV without -noVTK, -endTime 2e-9); the user's VTK/notes.md, VTK/<first subfolder>/notes.txt, postProcessing/fsi/0/notes.txt; ./Allrun again (same options): refused, or run? the user's files kept?
. "$(dirname "$0")/../lib.sh"
prev; O="${PREV/-noVTK/}"; run 250 ./Allrun $O -endTime 2e-9 > ../log.a1 2>&1; tail -2 ../log.a1 | cut -c1-200; echo "   VTK: $(ls VTK 2>/dev/null | head -5 | tr '\n' ' ')"
mkdir -p VTK; echo "# k09 vtk notes" > VTK/notes.md; s=$(ls -d VTK/*/ 2>/dev/null | head -1); [ -n "$s" ] && echo "k09 vtk sub" > ${s}notes.txt; echo "k09 fsi notes" > postProcessing/fsi/0/notes.txt
run 250 ./Allrun $O -endTime 2e-9 > ../log.a2 2>&1; grep -a -i -m4 'error\|refus\|overwrite\|already\|notes' ../log.a2 | cut -c1-220; kept "k09 vtk notes" "k09 vtk sub" "k09 fsi notes"
