#!/bin/bash
# c10: an empty .runLock (killed between create and write), then run
. "$(dirname "$0")/../lib.sh"
ind; : > .runLock
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror\|lock" log.run | head -8; tail -1 log.run; echo "rc=$rc"
