#!/bin/bash
# v56: hold step: holdGrowth 10 with holdDeltaT0 = maxDeltaT = 1e-3 s and a 3 s hold row (3000 hold steps, the s20 pattern in a hold) - timeout 150 s
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties holdGrowth 10; setd constant/indenterProperties holdDeltaT0 1e-3; setd constant/indenterProperties maxDeltaT 1e-3; sed -i 's/(B   hold    0       1)/(B   hold    0       3)/' constant/indenterProperties
timeout 150 cellIndentationFoam > log.run 2>&1; rc=$?; grep -a -A3 "FATAL\|#0" log.run | head -5 | cut -c1-300; echo "rc=$rc (124 timeout, 136 sigfpe)"; tail -1 postProcessing/indentation/force.dat
