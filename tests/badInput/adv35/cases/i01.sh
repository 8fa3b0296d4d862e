#!/bin/bash
# i01: ind: radius negative
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties radius -22.5e-6
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
