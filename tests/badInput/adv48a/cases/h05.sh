#!/bin/bash
# CASETIMEOUT=900
# h05 (class 5, the indentation's restart.h5 damaged: the killed smoke indentation (ik, 10x finer steps, killed 1 s after
# its first checkpoint), startFrom latestTime): (a) 64 B zeroed in the middle of restart.h5, (b) one bit flipped 100 B
# before its end, (c) cut to half, (d) emptied, (e) replaced by the finished run's (idn) restart.h5 (another run's
# checkpoint), (f) one force.dat value changed (a digit), (g) solid.h5 64 B zeroed in its middle. Each refused naming the
# file (and what is damaged), the results kept (force.dat, peaks.dat, solid.h5 unchanged); never a run from it.
. "$(dirname "$0")/../lib.sh"
idn; cp postProcessing/indentation/restart.h5 $W/other.h5; cd $W; rm -rf ind
ik; rm -f .runLock; cp -a . ../ikeep; R=postProcessing/indentation; ls $R | tr '\n' ' '; echo
one() { sums > ../s0; tryt 120 "$1" cellIndentationFoam; echo "   sig lines: $(sig) | changed: $(changed ../s0 | tr '\n' ' ')"; after; cd $W; rm -rf ind; cp -a ikeep ind; cd ind; }
s=$(stat -c %s $R/restart.h5); dd if=/dev/zero of=$R/restart.h5 bs=1 seek=$((s/2)) count=64 conv=notrunc 2>/dev/null; one "(a) restart.h5 64 B zeroed"
flip $R/restart.h5 $(( $(stat -c %s $R/restart.h5) - 100 )); one "(b) restart.h5 one bit near the end"
cutf $R/restart.h5 50; one "(c) restart.h5 cut to half"
: > $R/restart.h5; one "(d) restart.h5 emptied"
cp $W/other.h5 $R/restart.h5; one "(e) restart.h5 of the finished run"
/usr/bin/python3 -c "
import re; f='$R/force.dat'; L=open(f).read().split('\n'); i=[j for j,l in enumerate(L) if l and not l.startswith('#')][3]; m=list(re.finditer(r'[1-9]', L[i]))[-1]; k=m.start(); print('   force.dat row', i, L[i][:60]); L[i]=L[i][:k]+str(int(L[i][k])%9+1)+L[i][k+1:]; open(f,'w').write('\n'.join(L))"; one "(f) force.dat one digit"
s=$(stat -c %s $R/solid.h5); dd if=/dev/zero of=$R/solid.h5 bs=1 seek=$((s/2)) count=64 conv=notrunc 2>/dev/null; one "(g) solid.h5 64 B zeroed"
