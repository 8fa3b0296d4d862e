. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
xbd; rs6; rm -f .runLock; cp -a . ../keep; F=5e-09/uniform/fsiState
sete $F predictor extrapolatedd > /dev/null; cellBlastFoam -acceptEdited > run.log 2>&1; echo "(f) rc $?"; grep -a -A6 "Warning" run.log | grep -av "^ *$" | head -14
cd $W; rm -rf xblast; cp -a keep xblast; cd xblast; sete $F previousDeltaT 1e300 > /dev/null; cellBlastFoam -acceptEdited > run.log 2>&1; echo "(d) rc $?"; grep -a -A6 "Warning" run.log | grep -av "^ *$" | head -14
rm -rf $W
