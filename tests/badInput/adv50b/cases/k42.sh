#!/bin/bash
# k42 (class 3/2, the main job while a tutorial case it cleans is in use): in a project copy, the first shock tube's own Allrun started in its folder (a run in progress); then the main job started beside it. Expected: the main job's `./Allclean` of that case refused (the case's run lock: one run per case), the main job stopping with a message naming the case and the running process; the running case's own run unharmed (it ends rc 0 with its results); never the running case's files removed under it.
. "$(dirname "$0")/../lib.sh"
prj; P=$PWD; first=$(ls -d tutorials/verification/*/ | head -1); echo "   first case: $first"
(cd $first && ./Allrun > $W/own.log 2>&1) & o=$!; waitFor 120 bash -c "ls $P/$first/log.* > /dev/null 2>&1"; sleep 1; echo "   own run's lock: $(head -c 200 $first/.runLock 2>/dev/null | tr '\n' ';') $(ls -a $first | grep -i lock | tr '\n' ' ')"
tryt 300 "main job beside the running case" bash tutorials/Allrun; grep -a '^==' $W/try.log | tr '\n' ' '; echo
wait $o; echo "   own run rc=$? | $(tail -2 $W/own.log | tr '\n' ' ' | cut -c1-200)"; echo "   own results: errors.dat $(ls $first/postProcessing/riemannError/*/errors.dat 2>/dev/null | wc -l), png $(ls $first/*.png 2>/dev/null | wc -l)"
killIn $P
