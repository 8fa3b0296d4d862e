#!/bin/bash
# v45: duplicates: system/controlDict maxCo given twice (0.9, then 0.5 appended at the end)
. "$(dirname "$0")/../lib.sh"
blast; echo 'maxCo 0.5;' >> system/controlDict; grep -n maxCo system/controlDict; cellBlastFoam > log.run 2>&1; rc=$?; grep -a -A3 "FATAL" log.run | head -5 | cut -c1-300; echo "rc=$rc"
