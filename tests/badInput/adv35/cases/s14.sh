#!/bin/bash
# s14: ind: a hold of 1e9 s in the protocol (E hold 0 1e9) with maxDeltaT 5 s: 2e8 steps
. "$(dirname "$0")/../lib.sh"
ind; sed -i "s/^);/    (E hold 0 1e9)\n);/" constant/indenterProperties
timeout 60 cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc (124: still running after 60 s)"
