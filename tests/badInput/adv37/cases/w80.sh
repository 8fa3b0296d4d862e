#!/bin/bash
# w80: cellIndentationFoam controlDict at the edges: endTime 0, endTime -1, writeInterval 0, fieldWriteInterval -1, deltaT nan, startTime 1e300
. "$(dirname "$0")/../lib.sh"
ind; each system/controlDict "endTime 0" "endTime -1" "writeInterval 0" "fieldWriteInterval -1" "deltaT nan" "startTime 1e300" -- cellIndentationFoam; ls postProcessing 2>/dev/null
