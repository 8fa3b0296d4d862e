#!/bin/bash
# s19: blast: endTime 1 s (1e11 steps with the Courant limit)
. "$(dirname "$0")/../lib.sh"
blast; setd system/controlDict endTime 1
timeout 60 cellBlastFoam > log.run 2>&1; rc=$?; grep -A3 "FATAL" log.run | head -4; echo "rc=$rc (124 = still running at 60 s)"
