#!/bin/bash
# w79: thermophysicalProperties (water) at the edges: rho0 0, rho0 -1000, s -1.99, Gamma0 1e300, Cv 0, T0 nan, C0 1450 m/s written as 1.45 (km/s)
. "$(dirname "$0")/../lib.sh"
blast; f=constant/thermophysicalProperties; cp $f ../tp; for e in "rho0 0" "rho0 -1000" "s -1.99" "Gamma0 1e300" "Cv 0" "T0 nan" "C0 1.45"; do cp ../tp $f; k=${e%% *}; v=${e#* }; sed -i "0,/^\( *\)$k  *[^;]*;/s//\1$k $v;/" $f; try "$e" cellBlastFoam; done
echo "-- C0 1.45 (km/s written for m/s) in full:"; cp ../tp $f; sed -i "0,/^\( *\)C0  *[^;]*;/s//\1C0 1.45;/" $f; rm -rf solid postProcessing [1-9]*; run 120 cellBlastFoam > log.c0 2>&1; grep -a -A4 "FATAL" log.c0 | cut -c1-250
