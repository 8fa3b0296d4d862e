#!/bin/bash
# k43 (class 2, a main job re-run over a user's work in a tutorial folder): in a project copy, a finished shock tube (its own Allrun) in which the user keeps a note (notes.txt) and a result folder of their own (myResults/); then the main job started and SIGKILLed once it has moved past that case. Expected: the user's files kept or the main job refusing to clean a folder holding files that are not the tutorial's (as paperFigures/sweepCase do); never removed without a word.
. "$(dirname "$0")/../lib.sh"
prj; P=$PWD; first=$(ls -d tutorials/verification/*/ | head -1); (cd $first && ./Allrun > $W/own.log 2>&1); echo "   own run: $(ls $first/postProcessing/riemannError/*/errors.dat 2>/dev/null | wc -l) errors.dat"
echo "my note" > $first/notes.txt; mkdir -p $first/myResults; echo "my result" > $first/myResults/r.txt; cp $first/postProcessing/riemannError/*/errors.dat $W/errors.before 2>/dev/null
bash tutorials/Allrun > $W/main.log 2>&1 & m=$!; waitFor 600 bash -c "[ \$(grep -c '^==' $W/main.log) -ge 2 ]"; sleep 1; killIn $P; kill -KILL $m 2>/dev/null; wait $m 2>/dev/null
echo "   main job reached: $(grep -a '^==' $W/main.log | tr '\n' ' ') | said: $(grep -a -i -m2 'kept\|not the\|refus\|user' $W/main.log | cut -c1-200 | tr '\n' '|')"; where "my note" "my result"
