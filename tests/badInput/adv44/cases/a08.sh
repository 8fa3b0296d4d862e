#!/bin/bash
# a08 (class 2, fix19y in rhoRiemannFoam with function objects not tried before): waterPulseWall with, besides its probes, a fieldMinMax function object (minMaxP) and a second probes object (probesT, fields (T rho), one location); run to 4e-8 s; the user's own files named like their logs in the start segment: postProcessing/minMaxP/4e-08/fieldMinMax.dat, probesT/4e-08/T and probesT/4e-08/rho (plain text); restart to 8e-8 s: refused naming them, or written over?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/verification/waterPulseWall" $W/wp; cd $W/wp; ./Allclean > /dev/null 2>&1; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1
/usr/bin/python3 - system/controlDict <<'PY'
import sys; p = sys.argv[1]; t = open(p).read(); i = t.index('functions'); j = t.index('{', i) + 1
add = '\n    minMaxP { type fieldMinMax; libs ("libfieldFunctionObjects.so"); fields (p); writeControl timeStep; }\n    probesT { type probes; libs ("libsampling.so"); fields (T rho); probeLocations ((50e-6 0 0)); writeControl timeStep; }\n'
open(p, 'w').write(t[:j] + add + t[j:])
PY
sed -i "s/^endTime .*/endTime 4e-8;/" system/controlDict; run 200 rhoRiemannFoam > log.first 2>&1; fatal log.first 3; echo "   first: times $(ls -d [1-9]* | tr '\n' ' '); postProcessing: $(cd postProcessing && find . -type f | sort | tr '\n' ' ')"
P=postProcessing; mkdir -p $P/minMaxP/4e-08 $P/probesT/4e-08; echo "a08 my minmax table" > $P/minMaxP/4e-08/fieldMinMax.dat; echo "a08 my T notes" > $P/probesT/4e-08/T; echo "a08 my rho notes" > $P/probesT/4e-08/rho
latest; sed -i "s/^endTime .*/endTime 8e-8;/" system/controlDict; sums > ../s; tryf "restart 4e-8 -> 8e-8 s" rhoRiemannFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"; kept "a08 my minmax table" "a08 my T notes" "a08 my rho notes"
