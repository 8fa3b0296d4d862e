#!/bin/bash
# t42: planeWave on a finished 20 um column run to 20 ns, with -Z 30e-6 (not the case's column) and with no -Z (default 100e-6): must be refused or say the column differs
. "$(dirname "$0")/../lib.sh"
blast; setd system/controlDict endTime 2e-8; setd system/controlDict writeInterval 1e-8; cellBlastFoam > log.first 2>&1 || echo "run failed"
for z in 20e-6 30e-6 default; do
  if [ $z = default ]; then planeWave -dz 50e-9 -check > log.pw.$z 2>&1; else planeWave -Z $z -dz 50e-9 -check > log.pw.$z 2>&1; fi; rc=$?
  echo "== -Z $z: rc=$rc"; grep -i "error\|FAIL\|arrival\|column" log.pw.$z | head -6 | cut -c1-230
done
planeWave -dz 50e-9 > log.pw.nocheck 2>&1; echo "== no -Z, no -check: rc=$?"; grep -v "^#" postProcessing/planeWave/0/measures.dat | head -3 | cut -c1-200
head -3 postProcessing/fluidProbes/0/p | cut -c1-120; grep -v "^#" postProcessing/fluidProbes/0/p | tail -1 | cut -c1-120
