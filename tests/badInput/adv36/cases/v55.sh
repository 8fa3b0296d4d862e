#!/bin/bash
# v55: hold step: holdDeltaT0 10 s above maxDeltaT 1e-3 s
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties holdDeltaT0 10; setd constant/indenterProperties maxDeltaT 1e-3; timeout 250 cellIndentationFoam > log.run 2>&1; rc=$?; grep -a -A3 FATAL log.run | head -5 | cut -c1-300; echo "rc=$rc"; tail -1 postProcessing/indentation/force.dat
