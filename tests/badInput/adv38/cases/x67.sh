#!/bin/bash
# x67: cellIndentationFoam controlDict output entries at edges never tried: checkpointInterval 1e300, fieldWriteInterval 1e300, checkpointInterval 1e-300: accepted sensibly (one checkpoint/write at the end?) or refused with the range?
. "$(dirname "$0")/../lib.sh"
ind; grep -a "Interval" system/controlDict; each system/controlDict "checkpointInterval 1e300" "fieldWriteInterval 1e300" "checkpointInterval 1e-300" -- cellIndentationFoam
