#!/bin/bash
# i31: ind: indenterProperties missing
. "$(dirname "$0")/../lib.sh"
ind; rm constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
