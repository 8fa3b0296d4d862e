#!/bin/bash
# CASETIMEOUT=600
# p16 (new, class 4: OpenFOAM's floating-point trap switched off by the environment, FOAM_SIGFPE=false, as some users'
# shells set it): inputs whose overflow or invalid operation the trap turned into a stop: (a) the short preview (sb) with
# 0/p's pulse table pressures x1e150 (beyond any state of water), (b) the sod tube with pL = 1e300 in riemannProblemDict
# (setRiemannProblem, then rhoRiemannFoam), each with the default environment and with FOAM_SIGFPE=false. Expected: the
# same refusal both ways (our own checks, not the trap), rc != 0; with the trap off, a run that ends rc 0 with nan or inf
# in its fields = SILENT; with the trap on, sigFpe without our message = CRASH.
. "$(dirname "$0")/../lib.sh"
nanf() { echo "   nan/inf in written fields: $(grep -a -l -i 'nan\|inf' [1-9]*/p [1-9]*/rho 2>/dev/null | tr '\n' ' ' | cut -c1-200) | times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"; }
sb; /usr/bin/python3 - 0/p <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read()
def sc(m): return '(%s %s)' % (m.group(1), repr(float(m.group(2)) * 1e150))
i = t.index('boundaryField'); t2 = re.sub(r'\(\s*([-+0-9.eE]+)\s+([-+0-9.eE]+)\s*\)', sc, t[i:]); open(p, 'w').write(t[:i] + t2); print('   0/p pulse pairs scaled x1e150: %d' % len(re.findall(r'\(\s*[-+0-9.eE]+\s+[-+0-9.eE]+\s*\)', t[i:])))
P
cp -a . $W/b0; tryt 200 "(a1) pulse x1e150, default environment" cellBlastFoam; echo "   sig: $(sig) | said: $(msg 3 | cut -c1-250)"; nanf
cd $W; rm -rf blast; cp -a b0 blast; cd blast; tryt 200 "(a2) pulse x1e150, FOAM_SIGFPE=false" env FOAM_SIGFPE=false cellBlastFoam; echo "   sig: $(sig) | said: $(msg 3 | cut -c1-250)"; nanf
cd $W; sod; grep -n "pL\|p  *[0-9]" system/riemannProblemDict | head -3 | sed 's/^/   riemannProblemDict: /'
cd $W; rm -rf sod; cp -r $ROOT/tutorials/verification/sodIdealGas sod; cd sod; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1
sed -i '0,/p       1e5;/s//p       1e300;/' system/riemannProblemDict; grep -n "1e300" system/riemannProblemDict | sed 's/^/   /'
tryt 100 "(b0) setRiemannProblem with left p 1e300" setRiemannProblem; echo "   sig: $(sig) | said: $(msg 3 | cut -c1-250)"
cp -a . $W/s0; sed -i 's/^endTime .*/endTime 1e-6;/' system/controlDict
tryt 200 "(b1) rhoRiemannFoam, default environment" rhoRiemannFoam; echo "   sig: $(sig) | said: $(msg 3 | cut -c1-250)"; nanf
cd $W; rm -rf sod; cp -a s0 sod; cd sod; sed -i 's/^endTime .*/endTime 1e-6;/' system/controlDict
tryt 200 "(b2) rhoRiemannFoam, FOAM_SIGFPE=false" env FOAM_SIGFPE=false rhoRiemannFoam; echo "   sig: $(sig) | said: $(msg 3 | cut -c1-250)"; nanf
