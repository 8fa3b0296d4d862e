#!/bin/bash
# b41 (class 5, an indentation's checkpoint files of odd kinds at a restart): a run (10x finer steps) SIGKILLed after its first checkpoint; then restart.h5 (a) emptied, (b) a symbolic link to ANOTHER run's restart.h5 (the same inputs, killed later), (c) replaced by a directory; solid.h5 (d) a directory, (e) a link to the other run's solid.h5: each refused naming the file (or (b)/(e) continued to a result equal to a clean run's, the link not written through), nothing of the other run changed?
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cp -r $W/ind $W/other; cp -r $W/ind $W/ref
(cd $W/ref && cellIndentationFoam > log.ref 2>&1; echo "   reference run rc=$?")
(cd $W/other && { cellIndentationFoam > log.o 2>&1 & p=$!; waitFor 120 test -f postProcessing/indentation/restart.h5; sleep 3; kill -KILL $p; wait $p 2>/dev/null; }; md5sum postProcessing/indentation/* > ../om)
cellIndentationFoam > log.first 2>&1 & p=$!; waitFor 120 test -f postProcessing/indentation/restart.h5; sleep 1; kill -KILL $p; wait $p 2>/dev/null; latest; P=postProcessing/indentation; cp -a $P ../saved; sums > ../before
: > $P/restart.h5; tryf "(a) restart.h5 empty" cellIndentationFoam; rm -rf $P; cp -a ../saved $P
rm $P/restart.h5; ln -s $W/other/$P/restart.h5 $P/restart.h5; tryf "(b) restart.h5 a link to the other run's" cellIndentationFoam; echo "   (b) restart.h5 now: $(test -L $P/restart.h5 && echo link || echo file)"; [ -f $P/peaks.dat ] && cmp -s $P/peaks.dat $W/ref/$P/peaks.dat && echo "   (b) peaks.dat equal to the reference" ; rm -rf $P; cp -a ../saved $P
rm $P/restart.h5; mkdir $P/restart.h5; tryf "(c) restart.h5 a directory" cellIndentationFoam; rm -rf $P; cp -a ../saved $P
rm $P/solid.h5; mkdir $P/solid.h5; tryf "(d) solid.h5 a directory" cellIndentationFoam; rm -rf $P; cp -a ../saved $P
rm $P/solid.h5; ln -s $W/other/$P/solid.h5 $P/solid.h5; tryf "(e) solid.h5 a link to the other run's" cellIndentationFoam; echo "   (e) solid.h5 now: $(test -L $P/solid.h5 && echo link || echo file)"
cd $W/other; echo "   the other run's files: $(md5sum -c ../om 2>&1 | awk '{print $2}' | sort | uniq -c | tr '\n' ' ')"
