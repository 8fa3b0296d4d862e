#!/bin/bash
# y19: a whole .writeCommitted, but (a) a file it lists removed (2e-09/U gone), (b) a file it does not list added (2e-09/p.orig, a user's copy), (c) the marker's lines reordered (same content); restart from latestTime: (a) refused naming U/moved aside, (b), (c) continued?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cp -r . ../keep
rm 2e-09/U; try "(a) 2e-09/U removed" cellBlastFoam; ls -da [1-9]* 2>/dev/null | tr '\n' ' '; echo
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; cp 2e-09/p 2e-09/p.orig; try "(b) 2e-09/p.orig added" cellBlastFoam; ls -da [1-9]* 2>/dev/null | tr '\n' ' '; echo
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; { head -2 2e-09/.writeCommitted; tail -n +3 2e-09/.writeCommitted | tac; } > m; mv m 2e-09/.writeCommitted; try "(c) file lines reversed" cellBlastFoam; ls -da [1-9]* 2>/dev/null | tr '\n' ' '; echo
