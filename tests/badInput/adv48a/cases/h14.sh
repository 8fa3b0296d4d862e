#!/bin/bash
# CASETIMEOUT=900
# h14 (classes 4, 5: adv46b d41 (a), d49 (b), d57 varied): (a) the decomposed preview (finished on 2 ranks) with processor0
# missing, (b) with processor1/2e-09 removed only (its other times there), restarted on 2 ranks: each refused naming the
# rank's directory/time, no hang; (c) solid.h5 of the finished preview with one byte changed at 1/4 and (d) 3/4 of its
# size, and (e) 8 bytes zeroed 16 B before its end: solidToFoam refused naming the file and that it is damaged, nothing
# converted; (f) fsiProperties.allrun (included) with coupling { maxIter 0; }, (g) controlDict.allrun maxCo 2: refused
# naming the included file and its line, the entry and the range.
. "$(dirname "$0")/../lib.sh"
pblastDone; latest; blastEnd 3e-9 1e-9; rm -f .runLock; cp -a . ../pkeep
mv processor0 ../p0; tryt 90 "(a) processor0 missing" mpirun -np 2 cellBlastFoam -parallel; echo "   sig: $(sig)"; cd $W; rm -rf blast; cp -a pkeep blast; cd blast
rm -r processor1/2e-09; tryt 90 "(b) processor1/2e-09 removed" mpirun -np 2 cellBlastFoam -parallel; echo "   sig: $(sig) | p0: $(ls -d processor0/[0-9]* | tr '\n' ' ')| p1: $(ls -d processor1/[0-9]* | tr '\n' ' ')"; cd $W; rm -rf blast
bd; cp -a . ../bkeep; s=$(stat -c %s solid/solid.h5); echo "solid.h5 $s B"
for o in $((s/4)) $((3*s/4)); do /usr/bin/python3 -c "
f='solid/solid.h5'; b=bytearray(open(f,'rb').read()); b[$o]=(b[$o]+0x5a)%256; open(f,'wb').write(b)"; tryt 100 "(c/d) solid.h5 byte $o changed" solidToFoam solid/solid.h5; echo "   sig: $(sig) | time dirs: $(ls -d [0-9]* | tr '\n' ' ')"; cd $W; rm -rf blast; cp -a bkeep blast; cd blast; done
dd if=/dev/zero of=solid/solid.h5 bs=1 seek=$((s-16)) count=8 conv=notrunc 2>/dev/null; tryt 100 "(e) solid.h5 8 B zeroed near its end" solidToFoam solid/solid.h5; echo "   sig: $(sig)"; cd $W; rm -rf blast
blast; printf 'coupling\n{\n    maxIter 0;\n}\n' > constant/fsiProperties.allrun; tryt 40 "(f) fsiProperties.allrun maxIter 0" cellBlastFoam; rm -rf [1-9]* solid postProcessing; rm constant/fsiProperties.allrun
printf 'endTime 2e-9;\nwriteInterval 1e-9;\nmaxCo 2;\n' > system/controlDict.allrun; tryt 40 "(g) controlDict.allrun maxCo 2" cellBlastFoam
