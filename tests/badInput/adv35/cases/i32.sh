#!/bin/bash
# i32: ind: indenterProperties empty
. "$(dirname "$0")/../lib.sh"
ind; : > constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
