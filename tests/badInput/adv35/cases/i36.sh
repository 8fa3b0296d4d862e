#!/bin/bash
# i36: ind: postProcessing/indentation is a regular file (unwritable output)
. "$(dirname "$0")/../lib.sh"
ind; mkdir postProcessing; echo user > postProcessing/indentation
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"; cat postProcessing/indentation
