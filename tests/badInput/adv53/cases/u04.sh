#!/bin/bash
# CASETIMEOUT=600
# u04 (fix19i row "a water probe outside the mesh" (checkProbesInMesh), varied: another solver's OpenFOAM `probes`, two
# ranks of it, probes given through an #include'd file or a macro, a probe added at a restart, a probe exactly on the
# water's top face): (a) sb with a second probe exactly on the top boundary (x = 1e-7, y = the mesh's largest y): found or
# refused clearly; (b) sb with `#include "probesUser"` in fluidProbes (system/probesUser: probeLocations with a second
# probe (1e-7 1e-3 0), outside); (c) sb with the outside probe through a macro ($farProbe); (d) waterPulseWall
# (rhoRiemannFoam, OpenFOAM's probes) with a probe (200e-6 0 0) beyond the wall, serial; (e) the same on 2 ranks; (f) bd
# restarted to 3e-9 with the outside probe added. Expected: (b)-(f) refused at the start rc 1 naming the probe, its point,
# the file and line; -1e+300 / "Not Found" rows with rc 0 = UNCLEAR (SILENT if no word at all).
. "$(dirname "$0")/../lib.sh"
nf() { echo "   End $(grep -a -c '^End' $W/try.log) | Not Found/-1e+300 in logs: $(grep -a -l 'Not Found\|1e+300' postProcessing/*/*/* 2>/dev/null | tr '\n' ' ') | said: $(say 3 | cut -c1-350)"; }
sb; cp -a . $W/b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
ytop=$(/usr/bin/python3 -c "
import numpy as np; from neuronFsi import foamField as f; p = np.asarray(f.points('constant/polyMesh/points')); print(repr(float(p[:, 1].max())))"); echo "   mesh's largest y: $ytop"
sed -i "s|^\( *\)(9.9999999999999995e-08 1.0000000000000001e-05 0)|&\n\1(1e-7 $ytop 0)|" system/controlDict; grep -c "(1e-7 $ytop 0)" system/controlDict | sed 's/^/   probe on the top face added: /'
tryt 150 "(a) a probe exactly on the top face (y = $ytop)" cellBlastFoam; nf; back
printf 'probeLocations\n(\n    (9.9999999999999995e-08 1.0000000000000001e-05 0)\n    (1e-7 1e-3 0)\n);\n' > system/probesUser
/usr/bin/python3 - system/controlDict <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); t = re.sub(r'probeLocations\s*\(.*?\n\s*\);', '#include "probesUser"', t, flags=re.S); open(p, 'w').write(t)
P
grep -n 'probesUser' system/controlDict | sed 's/^/   controlDict: /'; tryt 150 "(b) the outside probe from #include probesUser (its line 4)" cellBlastFoam; nf; back
sed -i 's|^functions|farProbe (1e-7 1e-3 0);\n\nfunctions|' system/controlDict; sed -i "s|^\( *\)(9.9999999999999995e-08 1.0000000000000001e-05 0)|&\n\1\$farProbe|" system/controlDict; grep -n 'farProbe' system/controlDict | sed 's/^/   controlDict: /'
tryt 150 "(c) the outside probe through a macro \$farProbe" cellBlastFoam; nf; back
cd $W; cp -r $ROOT/tutorials/verification/waterPulseWall wp; cd wp; ./Allclean > /dev/null 2>&1; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1; wpEnd 2e-9
sed -i 's|^\( *\)(99.875e-6 0 0)|&\n\1(200e-6 0 0)|' system/controlDict; grep -c '(200e-6 0 0)' system/controlDict | sed 's/^/   wp probe beyond the wall added: /'; cp -a . $W/w0
tryt 150 "(d) rhoRiemannFoam, probe (200e-6 0 0) beyond the wall" rhoRiemannFoam; nf
cd $W; rm -rf wp; cp -a w0 wp; cd wp; wpDec; tryt 150 "(e) 2 ranks, probe (200e-6 0 0)" mpirun -np 2 rhoRiemannFoam -parallel; nf
cd $W; bd; rs; rm -f .runLock; sed -i "s|^\( *\)(9.9999999999999995e-08 1.0000000000000001e-05 0)|&\n\1(1e-7 1e-3 0)|" system/controlDict
tryt 200 "(f) bd restarted to 3e-9 with the outside probe added" cellBlastFoam; nf
