#!/bin/bash
# k04 (class 2, a probe field's name in a folder of ANOTHER function object, rhoRiemannFoam): waterPulseWall with probes fields (p) and a second probes function object probesU fields (U); during the run (after the first commit) the user copies probes/0/p into probesU/0/p (a real probes log, header and all, of a field probesU does not select); the run ends; -overwrite: refused naming probesU/0/p, kept?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/verification/waterPulseWall" $W/wp; cd $W/wp; ./Allclean > /dev/null 2>&1; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1
/usr/bin/python3 - system/controlDict <<'P'
import sys; p = sys.argv[1]; t = open(p).read()
t = t.replace('fields          (p U rho);', 'fields          (p);', 1)
t = t.replace('functions\n{', 'functions\n{\n    probesU\n    {\n        type probes;\n        libs ("libsampling.so");\n        writeControl timeStep;\n        writeInterval 1;\n        fields (U);\n        probeLocations ((50e-6 0 0));\n    }\n', 1); open(p, 'w').write(t)
P
sed -i "s/^endTime .*/endTime 8e-8;/" system/controlDict; grep -c probesU system/controlDict
rhoRiemannFoam > log.first 2>&1 & p=$!; waitFor 100 bash -c 'ls */.writeCommitted > /dev/null 2>&1'; cp postProcessing/probes/0/p postProcessing/probesU/0/p; echo "k04 user row" >> postProcessing/probesU/0/p; wait $p; echo "   run rc $?: times $(ls -d [0-9]* | tr '\n' ' '); probesU/0: $(ls postProcessing/probesU/0 | tr '\n' ' ')"
marks probesU/0/p; restart0; sums > ../s; tryf "-overwrite from 0" rhoRiemannFoam -overwrite; grep -a 'postProcessing' $W/try.log | grep -v '^-->' | head -4 | cut -c1-160; nochange ../s; kept "k04 user row"
