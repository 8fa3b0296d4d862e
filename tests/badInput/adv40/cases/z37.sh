#!/bin/bash
# z37: blast finished, `solidToFoam solid/solid.h5` (writes <time>/solid/), the user's notes.txt put into 2e-09/solid/ and a view.pvsm into constant/solid/, then solidToFoam again (as the Allrun does on every re-run): the user's files kept?
. "$(dirname "$0")/../lib.sh"
blastDone; solidToFoam solid/solid.h5 > log.s1 2>&1; echo "first rc=$?: $(ls -a 2e-09/solid | tr '\n' ' ')"; echo "my notes" > 2e-09/solid/notes.txt; ls -d constant/solid >/dev/null 2>&1 && echo "<pv/>" > constant/solid/view.pvsm
tryf "solidToFoam again" solidToFoam solid/solid.h5; echo "   2e-09/solid/notes.txt: $(cat 2e-09/solid/notes.txt 2>/dev/null || echo GONE); constant/solid/view.pvsm: $(cat constant/solid/view.pvsm 2>/dev/null || echo 'GONE (or no constant/solid)')"
