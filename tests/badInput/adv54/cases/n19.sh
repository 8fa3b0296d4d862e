#!/bin/bash
# CASETIMEOUT=900
# n19 (new, class 6/5: a full disk during an indentation that writes digests - the row flushed, its sidecar line not, or
# the reverse): the smoke indentation with 10x finer steps in a tmpfs of 600, 700, 800 KiB (the run needs more); each
# run stops on the full disk; then plotIndentation.py on what it left, the case copied out to a roomy disk and restarted
# (startFrom latestTime) to its end: force.dat, its sidecar and peaks.dat equal the uninterrupted run's, plotIndentation.py
# measures them. Expected: the full disk named, no signal; what is left read as a cut run (not "edited by hand"); the
# restart bitwise; else DATALOSS/SILENT/UNCLEAR as it falls.
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cp -a . $W/i0; tryt 600 "(0) uninterrupted" cellIndentationFoam; R=$PWD; du -sk postProcessing | awk '{print "   results: " $1 " KiB"}'
for s in 600k 700k 800k; do unmountAll; cd $W || exit 1; rm -rf $W/fs; tiny $s; cp -a $W/i0 $W/fs/case; cd $W/fs/case || { echo "   premise: no $W/fs/case"; continue; }; tryt 600 "(a) tmpfs $s" cellIndentationFoam; echo "   sig $(sig) | said: $(say 2 | cut -c1-200) | rows $(grep -vc '^#' postProcessing/indentation/force.dat 2>/dev/null) sidecar $(wc -l < postProcessing/indentation/force.dat.fnv1a64 2>/dev/null)"
  PL="plotIndentation.py on what is left ($s)" pi; echo "   said: $(say 1 | cut -c1-200)"
  [ -f system/controlDict ] || { echo "   premise: not in the case"; continue; }; rm -rf $W/c2; cp -a $W/fs/case $W/c2; cd $W/c2; latest; rm -f .runLock; tryt 600 "(b) restart with room ($s)" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-200) | force.dat $(cmp -s postProcessing/indentation/force.dat $R/postProcessing/indentation/force.dat && echo same || echo DIFFERS) | sidecar $(cmp -s postProcessing/indentation/force.dat.fnv1a64 $R/postProcessing/indentation/force.dat.fnv1a64 && echo same || echo DIFFERS) | peaks $(cmp -s postProcessing/indentation/peaks.dat $R/postProcessing/indentation/peaks.dat && echo same || echo DIFFERS)"
  pi; echo "   after the restart: $(pk)"; done
cd $W; unmountAll
