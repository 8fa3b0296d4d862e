#!/bin/bash
# v42: duplicates: 0/T internalField given twice (300 then 400)
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/^\(internalField .*\)$/\1\ninternalField uniform 400;/' 0/T; grep -n internalField 0/T; cellBlastFoam > log.run 2>&1; rc=$?; grep -a -A3 "FATAL" log.run | head -5 | cut -c1-300; echo "rc=$rc"
