#!/bin/bash
# i40: ind controlDict: checkpointInterval negative
. "$(dirname "$0")/../lib.sh"
ind; echo "checkpointInterval -1;" >> system/controlDict
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
