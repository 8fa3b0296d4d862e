#!/bin/bash
# v25: sod: the latest time's marker removed and its p zeroed in the middle, then a restart
. "$(dirname "$0")/../lib.sh"
sod; sed -i 's/^writeInterval .*/writeInterval 0.002;/' system/controlDict; rhoRiemannFoam > log.first 2>&1; ls -d [0-9]*|tr '\n' ' '; l=$(ls -d [0-9]* | sort -g | tail -1); rm $l/.writeCommitted; f=$l/p; s=$(stat -c%s $f); dd if=/dev/zero of=$f bs=1 seek=$((s/2)) count=64 conv=notrunc 2>/dev/null
sed -i 's/^endTime .*/endTime 0.009;/' system/riemannProblemDict
rhoRiemannFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A8 FATAL log.r | head -10
