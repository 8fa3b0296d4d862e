#!/bin/bash
# i10: ind: contactPatch nonexistent
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties contactPatch outerSurfac
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
