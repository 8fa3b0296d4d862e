#!/bin/bash
# i47: ind: checkpointInterval 1.5 (a label expected)
. "$(dirname "$0")/../lib.sh"
ind; echo "checkpointInterval 1.5;" >> system/controlDict
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -1 log.run; echo "rc=$rc"
