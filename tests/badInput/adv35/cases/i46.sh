#!/bin/bash
# i46: ind: radius written in hexadecimal float (0x1.7p-16, about 2.2e-5)
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^radius .*/radius 0x1.7p-16;/' constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -1 log.run; echo "rc=$rc"
