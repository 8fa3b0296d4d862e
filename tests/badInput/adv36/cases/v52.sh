#!/bin/bash
# v52: hold step: holdGrowth 10, holdDeltaT0 1e-3 s, maxDeltaT 1e6 s (top of its range)
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties holdGrowth 10; setd constant/indenterProperties holdDeltaT0 1e-3; setd constant/indenterProperties maxDeltaT 1e6; timeout 250 cellIndentationFoam > log.run 2>&1; rc=$?; grep -a -A3 FATAL log.run | head -5 | cut -c1-300; echo "rc=$rc"; tail -1 postProcessing/indentation/force.dat
