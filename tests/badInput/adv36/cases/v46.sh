#!/bin/bash
# v46: duplicates: constant/indenterProperties maxDeltaT given twice
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^\(maxDeltaT .*\)$/\1\nmaxDeltaT 0.5;/' constant/indenterProperties; grep -n maxDeltaT constant/indenterProperties; cellIndentationFoam > log.run 2>&1; rc=$?; grep -a -A3 FATAL log.run | head -5 | cut -c1-300; echo "rc=$rc"
