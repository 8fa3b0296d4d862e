#!/bin/bash
# v53: hold step: holdGrowth 1 (no growth) with holdDeltaT0 = maxDeltaT = 2e-3 s
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties holdGrowth 1; setd constant/indenterProperties holdDeltaT0 2e-3; setd constant/indenterProperties maxDeltaT 2e-3; timeout 250 cellIndentationFoam > log.run 2>&1; rc=$?; grep -a -A3 FATAL log.run | head -5 | cut -c1-300; echo "rc=$rc"; tail -1 postProcessing/indentation/force.dat
