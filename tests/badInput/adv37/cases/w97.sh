#!/bin/bash
# w97: blast axisymmetric to 14 ns (the pulse reaches the cell): solidProperties 'fixed ()' (no support, no axis condition) and 'fixed' without (axis 0): accepted without a word? the solid probes against the supported case
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 14e-9 7e-9; cellBlastFoam > log.first 2>&1; echo "supported rc=$?"; cp -r . ../ref; sp=constant/solidProperties
/usr/bin/python3 - <<'P'
import re; s=open('constant/solidProperties').read(); s=re.sub(r'\nfixed[^;]*?\);', '\nfixed ();', s, count=1, flags=re.S); open('constant/solidProperties','w').write(s)
P
foamDictionary -entry fixed $sp; rm -rf solid postProcessing [1-9]*; run 120 cellBlastFoam > log.nofix 2>&1; grep -a -i -m2 "fixed\|support\|warn.*solid\|rigid" log.nofix; fatal log.nofix 3
h=$(grep '^#' ../ref/postProcessing/solidProbes/0/solidProbes.dat | tail -1 | cut -c1-200); echo "header: $h"
echo "solidProbes last row (supported | fixed ()):"; tail -1 ../ref/postProcessing/solidProbes/0/solidProbes.dat | cut -c1-200; tail -1 postProcessing/solidProbes/0/solidProbes.dat | cut -c1-200
cp ../ref/$sp $sp; sed -i 's/^    (axis 0)  .*$//' $sp; foamDictionary -entry fixed $sp; rm -rf solid postProcessing [1-9]*; run 120 cellBlastFoam > log.noaxis 2>&1; fatal log.noaxis 3; grep -a -i -m2 "axis" log.noaxis | cut -c1-200; tail -1 postProcessing/solidProbes/0/solidProbes.dat | cut -c1-200
