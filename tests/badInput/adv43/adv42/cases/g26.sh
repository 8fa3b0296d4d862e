#!/bin/bash
# g26 (class 4, every number of the indentation's dictionaries): fresh smoke indentation; each entry of constant/indenterProperties (radius tolerance penaltyFactor maxDepthIncrement holdDeltaT0 holdGrowth maxDeltaT) and system/controlDict's fieldWriteInterval set in turn to nan, inf, -1, 1e400, or given twice; then protocol cells (row 2's amount, row 3's rate) nan / inf / -1 / 1e400: refused naming file, entry (row) and range before any output?
. "$(dirname "$0")/../lib.sh"
ind
badValues constant/indenterProperties "radius tolerance penaltyFactor maxDepthIncrement holdDeltaT0 holdGrowth maxDeltaT" -- cellIndentationFoam
badValues system/controlDict "fieldWriteInterval" -- cellIndentationFoam
cp constant/indenterProperties $W/ip.orig
for v in nan inf -1 1e400; do cp $W/ip.orig constant/indenterProperties; sed -i "s/(B   hold    0       1)/(B   hold    0       $v)/" constant/indenterProperties; grep -q "hold    0       $v" constant/indenterProperties || echo "   (row 2 edit not applied)"; tryf "row 2 amount $v" cellIndentationFoam; rm -rf postProcessing
  cp $W/ip.orig constant/indenterProperties; sed -i "s/(C1  load    10e-6/(C1  load    $v/" constant/indenterProperties; tryf "row 3 rate $v" cellIndentationFoam; rm -rf postProcessing; done
cp $W/ip.orig constant/indenterProperties
