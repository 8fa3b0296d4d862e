#!/bin/bash
# f28 (class 6, every point too large): pulseStudy with baseOptions -cell 1e-9 (a cell mesh of ~1e12 elements) on one point: refused before or at the point's cellMesh (its size estimate), the study ending non-zero within 200 s naming the point's log and the size; never meshing until killed.
. "$(dirname "$0")/../lib.sh"
study; sed -i 's/^baseOptions .*/baseOptions     (-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 1e-9 -Z 20e-6 -endTime 2e-9);/' system/pulseStudyDict
s=$(date +%s); tryt 240 "baseOptions -cell 1e-9" pulseStudy; echo "   took $(($(date +%s) - s)) s"; tail -3 $W/try.log | cut -c1-250
