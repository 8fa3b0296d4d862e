#!/bin/bash
# g32 (class 2, output folders kept on another file system through symbolic links): finished blast to 2 ns whose solid/ and postProcessing/ were moved to a tmpfs and replaced by symbolic links (a user short of space); (a) restart to 3 ns: equal to a clean restart's, links kept? (b) -overwrite from 0 (moving aside across the link): runs, old results removed only after the first commit, links kept, results equal to the original run's?
. "$(dirname "$0")/../lib.sh"
blastRef; mkdir -p $W/fs; mount -t tmpfs -o size=200000k tmpfs $W/fs || { echo "no tmpfs"; exit 0; }
cd $W/r; cp -r ref2 k; cd k; mv solid $W/fs/solid; mv postProcessing $W/fs/pp; ln -s $W/fs/solid solid; ln -s $W/fs/pp postProcessing
latest; blastEnd 3e-9 1e-9; tryf "(a) restart to 3 ns through the links" cellBlastFoam; echo "   solid: $(stat -c %F solid), postProcessing: $(stat -c %F postProcessing)"; cmpRef $W/r/ref
sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; blastEnd 2e-9 1e-9; tryf "(b) -overwrite from 0 through the links" cellBlastFoam -overwrite; echo "   solid: $(stat -c %F solid), postProcessing: $(stat -c %F postProcessing); times $(ls -d [1-9]* | tr '\n' ' '); hidden: $(ls -a solid postProcessing | grep '^\.[^.]' | tr '\n' ' ')"
echo "   vs the original 2 ns run: $(sameSeries $W/r/ref2 | awk '{print $1, $2}' | tr '\n' ' ') solid.h5 $(h5same solid/solid.h5 $W/r/ref2/solid/solid.h5)"; cd $W; umount $W/fs 2>/dev/null || { sleep 1; umount -l $W/fs; }
