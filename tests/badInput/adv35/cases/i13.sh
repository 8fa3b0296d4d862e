#!/bin/bash
# i13: ind: forceTarget negative
. "$(dirname "$0")/../lib.sh"
ind; echo 'forceTarget -1e-9;' >> constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
