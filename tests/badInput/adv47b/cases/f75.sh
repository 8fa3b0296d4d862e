#!/bin/bash
# f75 (class 2, a failing -overwrite over finished results): the finished sod case (0.007 written) re-run with -overwrite after (a) 0/T's internal field set to -1 (fails at the start: T <= 0 K) and (b) 0/p set to nan: each refused/failed rc != 0, the earlier 0.007 back in place (not left as .0.007.overwritten), its files unchanged; (c) the same after maxCo 2 (refused at read): nothing moved.
# (corrected after its first run: sod starts from latestTime; startFrom startTime set, as -overwrite needs)
. "$(dirname "$0")/../lib.sh"
sodDone; restart0; ls -d [0-9]* | tr '\n' ' '; echo; cp -r 0 ../zero0; sums > ../s0
sed -i 's/^internalField .*/internalField   uniform -1;/' 0/T; grep -c 'uniform -1;' 0/T; tryt 60 "(a) -overwrite with 0/T -1" rhoRiemannFoam -overwrite; ls -d [0-9]* .*overwritten* 2>/dev/null | tr '\n' ' '; echo; echo "   changed: $(changed ../s0)"
rm -rf 0; cp -r ../zero0 0; sed -i '0,/^internalField .*/s//internalField   uniform nan;/' 0/p; tryt 60 "(b) -overwrite with 0/p nan" rhoRiemannFoam -overwrite; ls -d [0-9]* .*overwritten* 2>/dev/null | tr '\n' ' '; echo; echo "   changed: $(changed ../s0)"
rm -rf 0; cp -r ../zero0 0; sete system/controlDict maxCo 2; tryt 60 "(c) -overwrite with maxCo 2" rhoRiemannFoam -overwrite; ls -d [0-9]* .*overwritten* 2>/dev/null | tr '\n' ' '; echo; echo "   changed: $(changed ../s0)"
