#!/bin/bash
# c07: a .runLock with garbage content (corrupted lock), then run
. "$(dirname "$0")/../lib.sh"
ind; printf 'garbage\x00\x01 here\n' > .runLock
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror\|lock" log.run | head -8; tail -1 log.run; echo "rc=$rc"
