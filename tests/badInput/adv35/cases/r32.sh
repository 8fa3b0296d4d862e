#!/bin/bash
# r32: ind: finished; restart latestTime with nothing changed (nothing left to run)
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sums > ../before
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A3 "FATAL" log.run | head -5; tail -1 log.run; echo "rc=$rc"; sums > ../after; cmp -s ../before ../after && echo "files unchanged"
