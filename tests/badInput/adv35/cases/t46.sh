#!/bin/bash
# t46: solidToFoam on restart.h5 (a checkpoint, not a results file)
. "$(dirname "$0")/../lib.sh"
indDone; solidToFoam postProcessing/indentation/restart.h5 > log.s 2>&1; rc=$?; grep -A2 FATAL log.s | head -3; tail -2 log.s; echo "rc=$rc"
