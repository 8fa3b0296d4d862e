#!/bin/bash
# i48: ind: radius followed by a double semicolon
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^radius .*/radius 22.5e-6;;/' constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -1 log.run; echo "rc=$rc"
