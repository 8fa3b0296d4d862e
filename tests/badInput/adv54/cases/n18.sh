#!/bin/bash
# CASETIMEOUT=900
# n18 (new, class 6: a CPU-time limit, `ulimit -t` - a batch queue's limit; the kernel sends SIGXCPU, default action: core
# dump/terminate): (a) bd restarted to 3e-8 under ulimit -t 4 (s of CPU); then the restart to 3e-8 without the limit
# against the uninterrupted p8-like run (3e-09/p bitwise; logs by sameSeries); (b) the smoke indentation with 10x finer
# steps under ulimit -t 3, then the restart to its end: force.dat and its sidecar equal the uninterrupted run's; (c)
# planeWave -dz 12.5e-9 under ulimit -t 2. Expected: each stopped (by the signal, or with a message), nothing half-written
# taken later: the restarts equal the uninterrupted runs; a Python traceback = CRASH low.
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 3e-8 1e-9; cp -a . $W/b0; rm -f .runLock; tryt 600 "(0) uninterrupted to 3e-8" cellBlastFoam; R=$PWD
cd $W; cp -a b0 b1; cd b1; rm -f .runLock; tryt 600 "(a) ulimit -t 4" bash -c 'ulimit -t 4; exec cellBlastFoam'; echo "   sig $(sig) | times $(ls -d [0-9]* | tr '\n' ' ' | cut -c1-150) | tail: $(tail -n 2 $W/try.log | tr '\n' ' ' | cut -c1-150)"
rm -f .runLock; tryt 600 "(a) restart without the limit" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-200) | 3e-08/p $(cmp -s 3e-08/p $R/3e-08/p && echo same || echo DIFFERS) | probe log $(cmp -s postProcessing/fluidProbes/0/p $R/postProcessing/fluidProbes/0/p && echo same || echo DIFFERS) | solidProbes $(cmp -s postProcessing/solidProbes/0/solidProbes.dat $R/postProcessing/solidProbes/0/solidProbes.dat && echo same || echo DIFFERS)"
cd $W; ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cp -a . $W/i0; tryt 600 "(0) indentation uninterrupted" cellIndentationFoam; I=$PWD
cd $W; cp -a i0 i1; cd i1; tryt 600 "(b) ulimit -t 3" bash -c 'ulimit -t 3; exec cellIndentationFoam'; echo "   sig $(sig) | rows $(grep -vc '^#' postProcessing/indentation/force.dat 2>/dev/null)"
latest; rm -f .runLock; tryt 600 "(b) restart without the limit" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-200) | force.dat $(cmp -s postProcessing/indentation/force.dat $I/postProcessing/indentation/force.dat && echo same || echo DIFFERS) | sidecar $(cmp -s postProcessing/indentation/force.dat.fnv1a64 $I/postProcessing/indentation/force.dat.fnv1a64 && echo same || echo DIFFERS) | peaks.dat $(cmp -s postProcessing/indentation/peaks.dat $I/postProcessing/indentation/peaks.dat && echo same || echo DIFFERS)"
cd $W; p8; tryt 300 "(c) planeWave -dz 12.5e-9 under ulimit -t 2" bash -c 'ulimit -t 2; exec planeWave -case . -dz 12.5e-9'; echo "   said: $(say 2 | cut -c1-200) | tail: $(tail -n 1 $W/try.log | cut -c1-150) | files: $(ls -la postProcessing/planeWave/0 | awk 'NR>3{print $NF ":" $5}' | tr '\n' ' ')"
