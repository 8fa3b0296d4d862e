#!/bin/bash
# i45: ind: radius with a unicode minus in the exponent (22.5e−6)
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^radius .*/radius 22.5e−6;/' constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -1 log.run; echo "rc=$rc"
