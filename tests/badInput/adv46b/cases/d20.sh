#!/bin/bash
# d20 (class 2, rhoRiemannFoam -dry-run-write and -dry-run on the finished sod tube): each refused over results or changes nothing.
. "$(dirname "$0")/../lib.sh"
sodDone; sums > ../s0; for o in -dry-run -dry-run-write; do tryt 100 "$o" rhoRiemannFoam $o; echo "   $(tail -1 $W/try.log | cut -c1-150)"; nochange ../s0; done; ls
