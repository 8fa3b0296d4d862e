#!/bin/bash
# i05: ind: protocol motion misspelt 'lod'
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/(A   load/(A lod/' constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
