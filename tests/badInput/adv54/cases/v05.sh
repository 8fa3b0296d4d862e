#!/bin/bash
# CASETIMEOUT=600
# v05 (fix19j row "a keyword given twice across an #include", varied: other dictionaries and other include forms): (a) the
# sod tube's system/riemannProblemDict: left { #include "leftUser" (p 2e5;) p 1e5; ... } then setRiemannProblem; (b) the
# preview's system/fvSolution riemann { #includeIfPresent "riemannUser" (riemannSolver HLL;) riemannSolver HLLC; }, short
# run; (c) constant/solidProperties with `#sinclude "viscUser"` (shearViscosity 0.5 at the top level) then the
# file's own shearViscosity: short run; (d) the same in constant/dynamicMeshDict (an entry of ours? whatever the solver
# reads: motionSolver given through an #include and again); (e) cellMeshDict.allrun's duplicate across its own #include
# (adv53 l30 (f)). Expected: each duplicate refused naming both places (or, where an include cannot hold the scope's
# entries by design, a documented rule); the included value replaced without a word = UNCLEAR (o07's class).
. "$(dirname "$0")/../lib.sh"
sod; printf 'p 2e5;\n' > system/leftUser; /usr/bin/python3 - system/riemannProblemDict <<'P'
import sys
p = sys.argv[1]; t = open(p).read(); t = t.replace("left\n{\n", 'left\n{\n    #include "leftUser"\n', 1); open(p, "w").write(t)
P
grep -n -A3 '^left' system/riemannProblemDict | head -4; rm -rf 0; cp -r 0.orig 0; tryt 120 "(a) riemannProblemDict left{} p by #include and again" setRiemannProblem; echo "   said: $(say 2 | cut -c1-300) | 0/p left: $(grep -a -m1 -A3 'internalField' 0/p | tail -n 1 | cut -c1-60)"
cd $W; sb; printf 'riemannSolver HLL;\n' > system/riemannUser; /usr/bin/python3 - system/fvSolution <<'P'
import sys, re
p = sys.argv[1]; t = open(p).read(); t = re.sub(r'(\nriemann\s*\{\s*\n)', r'\1    #includeIfPresent "riemannUser"\n', t, count=1); open(p, "w").write(t)
P
grep -n -A3 '^riemann' system/fvSolution | head -4; tryt 200 "(b) fvSolution riemann{} riemannSolver by #includeIfPresent and again" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-300)"
cd $W; rm -rf blast; sb; printf 'shearViscosity 0.5;\n' > constant/viscUser; grep -n '^shearViscosity\|^ *shearViscosity' constant/solidProperties | head -2
/usr/bin/python3 - constant/solidProperties <<'P'
import sys, re
p = sys.argv[1]; t = open(p).read(); m = re.search(r'\n(\s*)shearViscosity', t); t = t[:m.start()] + '\n' + m.group(1) + '#sinclude "viscUser"' + t[m.start():]; open(p, "w").write(t)
P
grep -n -B1 'shearViscosity ' constant/solidProperties | head -3; tryt 200 "(c) solidProperties shearViscosity by #sinclude and again" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-300)"
cd $W; rm -rf blast; sb; grep -v '^ *//' constant/dynamicMeshDict | grep -v '^ *$' | sed -n 8,14p
k=$(grep -v '^ *//\|^ *$\|FoamFile\|^[{}]\|version\|format\|class\|object\|location' constant/dynamicMeshDict | head -n 1 | awk '{print $1}'); v=$(grep -m1 "^ *$k " constant/dynamicMeshDict | sed "s/^ *$k *//"); echo "   first entry: $k = $v"
printf '%s %s\n' "$k" "$v" > constant/dynUser; sed -i "0,/^ *$k /s//#include \"dynUser\"\n$k /" constant/dynamicMeshDict; grep -n -B1 "^$k " constant/dynamicMeshDict | head -3
tryt 200 "(d) dynamicMeshDict $k by #include and again" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-300)"
cd $W; mdir; printf 'membraneLayers 2;\n' > system/layersUser; printf '#include "layersUser"\nmembraneLayers 1;\n' > system/cellMeshDict.allrun; grep -q 'cellMeshDict.allrun' system/cellMeshDict || echo '#sinclude "cellMeshDict.allrun"' >> system/cellMeshDict
tryt 200 "(e) cellMeshDict.allrun membraneLayers by its own #include and again" cellMesh; echo "   said: $(say 2 | cut -c1-300) | layers: $(grep -a -i 'layers' $W/try.log | head -n 1 | cut -c1-100)"
