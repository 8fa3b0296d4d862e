#!/bin/bash
# o11: ind Allrun twice in a copy (re-run over results)
. "$(dirname "$0")/../lib.sh"
ind; cp "$ROOT/tutorials/indentation/averageCell"/All* .; ./Allrun > l1 2>&1; echo "rc1=$?"; sums > ../before; ./Allrun 2>&1 | tail -4; echo "rc2=${PIPESTATUS[0]}"; sums > ../after; cmp -s ../before ../after && echo unchanged || { echo CHANGED; diff ../before ../after | head; }
