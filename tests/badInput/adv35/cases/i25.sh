#!/bin/bash
# i25: ind: radius in um (22.5: wrong units)
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties radius 22.5
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
