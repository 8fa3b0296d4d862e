. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
pbd; rs; rm -f .runLock
python3 - <<'P'
f='processor1/2e-09/rhoE'; s=open(f,'rb').read(); k=s.find(b'boundaryField'); k=s.find(b'procBoundary1to0',k); print(s[k:k+400])
P
setbb processor1/2e-09/rhoE procBoundary1to0 0 999789750000000.0
mpirun -np 2 cellBlastFoam -parallel -acceptEdited > run.log 2>&1; echo "rc $?"; grep -a -n "FATAL\|cell\|another" run.log | head; cp run.log /tmp/adv50a-man/t5run.log
rm -rf $W
