#!/bin/bash
# o22: blast: cellBlastFoam -overwrite over a finished case, one late-refused input at a time (the scope of o05): which earlier results are changed by the refused run
. "$(dirname "$0")/../lib.sh"
blastDone; cp -r "$W/blast" "$W/done"
try() { # try NAME COMMAND: a fresh copy of the finished case, the edit, -overwrite, the result files changed
  rm -rf "$W/t"; cp -r "$W/done" "$W/t"; cd "$W/t"; sums | grep -v "  \./\(system\|constant\|0\|0\.orig\)/" > ../before; eval "$2"
  cellBlastFoam -overwrite > log.ow 2>&1; rc=$?; sums | grep -v "  \./\(system\|constant\|0\|0\.orig\)/" > ../after
  ch=$(diff ../before ../after | grep "^>" | sed 's/^> [0-9a-f]*  \.\///' | tr '\n' ' ')
  echo "$1: rc=$rc; $(grep -A1 FATAL log.ow | tail -1 | cut -c1-110); changed: ${ch:-nothing}"; cd "$W"; }
try heightFraction "setd constant/solidProperties interfaceProbe/heightFraction 1.5"
try onNonConvergence "setd constant/fsiProperties coupling/onNonConvergence wran"
try T0negative "sed -i 's/^internalField .*/internalField uniform -10;/' 0/T"
try reconstructP "sed -i 's/reconstruct(p)      MUSCL;/reconstruct(p) MUSLC;/' system/fvSchemes"
try interpolationScheme "sed -i 's/interpolationScheme cellPoint;/interpolationScheme cellPont;/' system/controlDict"
try maxCo0 "setd system/controlDict maxCo 0"
try axisDirection0 "setd constant/fsiProperties interface/axisDirection '(0 0 0)'"
try Gamma0negative "setd constant/thermophysicalProperties mieGruneisenCoeffs/Gamma0 -0.1"
try pulseTableNotIncreasing "sed -i 's/(1e-10    50000000)/(3e-9 50000000)/; s/(5e-09    50000000)/(2e-9 50000000)/' 0/p"
try riemannSolver "sed -i 's/riemannSolver   HLLC;/riemannSolver HLLCC;/' system/fvSolution"
