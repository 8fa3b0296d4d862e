#!/bin/bash
# f13 (class 3/2, Allclean during a run): the preview (with the tutorial's Allclean) restarted to 8e-9 in the background; after its 3e-09 write, ./Allclean. Correct: Allclean refuses while the case is in use (naming the run), or the run stops with an error naming what vanished; never a crash (signal), never the run ending rc 0 with its results gone, never results half-removed without a word.
. "$(dirname "$0")/../lib.sh"
bd; cp $ROOT/tutorials/blast/axisymmetricPreview/Allclean .; blastEnd 8e-9 1e-9; latest; cellBlastFoam > log.bg 2>&1 & p=$!; waitFor 90 test -f 3e-09/.writeCommitted
tryt 60 "Allclean during the run" ./Allclean; cat $W/try.log | head -5 | cut -c1-200
wait $p; echo "   run rc=$?: $(grep -a -m2 -A2 'FATAL\|Error\|error' log.bg | head -4 | tr '\n' ' ' | cut -c1-300)"; tail -2 log.bg | cut -c1-200; after; ls
