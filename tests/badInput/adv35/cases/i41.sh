#!/bin/bash
# i41: ind: a blast-only solidProperties entry (shearViscosity) in an indentation case
. "$(dirname "$0")/../lib.sh"
ind; echo "shearViscosity 0.2;" >> constant/solidProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
