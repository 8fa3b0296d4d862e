#!/bin/bash
# b32 (class 5, solidToFoam on odd solid.h5 files): a blast run to 2 ns; solidToFoam on (a) solid.h5 cut to half its size, (b) a symbolic link to ANOTHER run's solid.h5 (another blast case), (c) a directory named solid.h5, (d) a FIFO named x.h5, (e) an empty file: each refused naming the file (or (b) converted as the file it is), no crash, no partial time folders left as if good?
. "$(dirname "$0")/../lib.sh"
blastDone; cp solid/solid.h5 ../full.h5; s=$(stat -c %s ../full.h5); head -c $((s/2)) ../full.h5 > ../half.h5; mkdir -p ../dir.h5; mkfifo ../fifo.h5; : > ../empty.h5
for f in ../half.h5 ../dir.h5 ../fifo.h5 ../empty.h5; do tryf "solidToFoam $f" solidToFoam $f; echo "   2e-09/: $(ls 2e-09 | tr '\n' ' ')"; rm -rf constant/solid [0-9]*/solid; done
cd $W; mv blast other; blastDone; cd $W/blast; ln -s $W/other/solid/solid.h5 ../link.h5; tryf "solidToFoam a link to another run's solid.h5" solidToFoam ../link.h5; echo "   2e-09/: $(ls 2e-09 | tr '\n' ' ')"
