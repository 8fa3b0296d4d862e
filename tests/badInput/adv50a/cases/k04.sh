#!/bin/bash
# CASETIMEOUT=900
# k04 (adv49b i38 / fix19f's writeInterval-as-a-count varied): whole counts at 2^31-1, 2^31, 2^53, 2^53+1, 2^63 and
# forms of the limit (2.147483647e9, 2147483647.0, 0x7fffffff, +2147483647, 2147483647.5) for: (a) the preview's
# controlDict writeControl timeStep + writeInterval (cellBlastFoam, endTime 2e-11); (b) the function object fluidProbes'
# writeInterval (writeControl timeStep; OpenFOAM's timeControl); (c) fluidProbes' executeControl timeStep +
# executeInterval; (d) the smoke indentation's writeInterval (writeControl timeStep already); (e) the sod tube with
# writeControl timeStep (rhoRiemannFoam); (f) writePrecision and timePrecision at 2^53 (j06 did 2^31-1, 2^31, 2^63).
# Inside [1, 2147483647] accepted (the run starts or ends), beyond refused rc 1 naming the file, the entry, the digits as
# written and the range; never a signal (i38 was a sigFpe in Time::readDict), never a value cut or wrapped.
. "$(dirname "$0")/../lib.sh"
V="2147483647 2147483648 9007199254740992 9007199254740993 9223372036854775808 2.147483647e9 2147483647.0 0x7fffffff +2147483647 2147483647.5"
blast; short; rm -f .runLock; cp -a . ../b0
res() { echo "   sig: $(sig) | End: $(grep -a -c '^End' $W/try.log) | times: $(ls -d [0-9]* 2>/dev/null | tr '\n' ' ') | msg: $(msg 4 | cut -c1-450)"; }
back() { cd $W; rm -rf $1; cp -a $2 $1; cd $1; }
for v in $V; do sed -i '/^writeControl /d; /^writeInterval /d' system/controlDict; printf 'writeControl timeStep;\nwriteInterval %s;\n' $v >> system/controlDict
  tryt 90 "(a) controlDict writeControl timeStep, writeInterval $v: cellBlastFoam" cellBlastFoam; res; back blast b0; done
for v in 2147483647 2147483648 9007199254740993 9223372036854775808 2.147483647e9; do subset system/controlDict fluidProbes writeInterval $v > /dev/null
  tryt 90 "(b) fluidProbes writeInterval $v (writeControl timeStep): cellBlastFoam" cellBlastFoam; res; back blast b0; done
for v in 2147483647 2147483648 9223372036854775808; do subset system/controlDict fluidProbes executeControl timeStep > /dev/null; subset system/controlDict fluidProbes executeInterval $v > /dev/null
  tryt 90 "(c) fluidProbes executeControl timeStep, executeInterval $v: cellBlastFoam" cellBlastFoam; res; back blast b0; done
for v in 9007199254740992 9007199254740993; do for e in writePrecision timePrecision; do sete system/controlDict $e $v
  tryt 90 "(f) controlDict $e $v: cellBlastFoam" cellBlastFoam; res; back blast b0; done; done
cd $W; ind; rm -f .runLock; cp -a . ../i0
for v in 2147483647 2147483648 9007199254740993 2.147483647e9; do sed -i "s/^writeInterval .*/writeInterval $v;/" system/controlDict
  tryt 90 "(d) smoke indentation writeInterval $v: cellIndentationFoam" cellIndentationFoam; echo "   sig: $(sig) | End: $(grep -a -c '^End' $W/try.log) | msg: $(msg 4 | cut -c1-450)"; back ind i0; done
cd $W; sod; rm -f .runLock; cp -a . ../s0
for v in 2147483647 2147483648 9223372036854775808 2147483647.5; do sed -i '/^writeControl /d; /^writeInterval /d' system/controlDict; printf 'writeControl timeStep;\nwriteInterval %s;\n' $v >> system/controlDict
  tryt 90 "(e) sod writeControl timeStep, writeInterval $v: rhoRiemannFoam" rhoRiemannFoam; res; back sod s0; done
