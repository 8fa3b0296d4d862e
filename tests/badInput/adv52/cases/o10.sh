#!/bin/bash
# CASETIMEOUT=900
# o10 (fix19h's water probes below the water's top, adv51 n02, varied: a probe outside the water sideways, one in the
# cell): (a) quarter3D's Allrun with -box 20e-6 (its smoke sizes, -np 1, -noRun): its probes at x = y = 25e-6 m lie
# outside the 20 um box sideways; which does the Allrun keep? a run to 2e-11: the probe file's header and rows (-1e+300?);
# (b) the preview (sb) with a fifth probe by hand inside the cell (1e-7 3e-6 0: solid, no water cell) - documented as
# OpenFOAM's warning and -1e+300 rows (a probe in no cell given by hand); (c) the preview's Allrun -Z 9e-6 -noRun
# (the 10 um probe is above the water; the column under the cell's top?). Each: the probe dropped or refused naming it;
# -1e+300 rows written as a measured value with rc 0 = UNCLEAR (a, c) / documented (b).
. "$(dirname "$0")/../lib.sh"
pf() { local F=$(ls -d postProcessing/fluidProbes/*/p 2>/dev/null | head -1); [ -n "$F" ] && echo "   $F: $(grep -a -c 'Not Found' $F) 'Not Found' | probes: $(grep -a '^# Probe' $F | tr -s ' ' | tr '\n' ' ' | cut -c1-300) | rows with 1e+300: $(grep -a -v '^#' $F | grep -c '1e+300') of $(grep -a -vc '^#' $F)" || echo "   no probe file"; echo "   warnings: $(grep -a -c -i 'warning' $W/try.log) $(grep -a -m1 -i -A1 'warning' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-200)"; }
cd $W; cp -r $ROOT/tutorials/blast/quarter3D q1; cd q1
tryt 600 "(a0) quarter3D Allrun -noRun -box 20e-6 -np 1 (smoke sizes)" ./Allrun -noRun -noPlots -np 1 -box 20e-6 -h 1e-6 -dz 1e-6 -lateral 2e-6 -far 5e-6 -cell 1.4e-6 -endTime 2e-11
echo "   controlDict.allrun probes: $(grep -o 'probeLocations[^;]*;' system/controlDict.allrun 2>/dev/null | cut -c1-300)"; tail -3 $W/try.log | sed 's/^/   out: /'
sed -i '/^writeInterval/d' system/controlDict.allrun; echo 'writeInterval 1e-11;' >> system/controlDict.allrun
tryt 300 "(a) cellBlastFoam to 2e-11" cellBlastFoam; pf
cd $W; sb; /usr/bin/python3 - system/controlDict <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); m = re.search(r'probeLocations\s*\((.*?)\n\s*\);', t, re.S)
t = t[:m.end() - 2].rstrip() + '\n            (1e-7 3e-6 0)\n        );' + t[m.end():]; open(p, 'w').write(t)
P
grep -A5 probeLocations system/controlDict | tr -s ' ' | tr '\n' ' ' | sed 's/^/   /'; echo
tryt 120 "(b) a probe by hand inside the cell (1e-7 3e-6 0)" cellBlastFoam; pf
cd $W; cp -r $ROOT/tutorials/blast/axisymmetricPreview p9; cd p9; tryt 400 "(c) preview Allrun -Z 9e-6 -noRun" ./Allrun -noRun -noPlots -noVTK -h 0.5e-6 -far 4e-6 -dz 0.5e-6 -cell 1e-6 -Z 9e-6
echo "   said: $(grep -a -m2 -i 'error\|refus' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300) | controlDict.allrun probes: $(grep -o 'probeLocations[^;]*;' system/controlDict.allrun 2>/dev/null | cut -c1-200)"
