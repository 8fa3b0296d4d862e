#!/bin/bash
# i27: ind: misspelt keyword in controlDict (fieldWriteIntervall)
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^fieldWriteInterval /fieldWriteIntervall /' system/controlDict
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
