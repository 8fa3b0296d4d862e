#!/bin/bash
# g34 (class 2, g10 isolated): a blast run to 2 ns and restarted to 3 ns (both finished, every segment committed); then, each alone in a copy, the user's file in a function object's folder, and -overwrite from 0: (a) notes.md ("# My analysis") in the restart's segment postProcessing/fsi/2e-09/; (b) a plain notes.txt there; (c) notes.md ("# ...") in the start segment postProcessing/fsi/0/; (d) notes.md in solidProbes/2e-09/: refused naming the file, or removed?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cellBlastFoam > log.second 2>&1; sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; blastEnd 2e-9 1e-9; echo "   segments: fsi $(ls postProcessing/fsi | tr '\n' ' '); 3e-09/.writeCommitted log lines: $(grep -a -c 'log' 3e-09/.writeCommitted)"; cd ..; mv blast base
part() { rm -rf c; cp -r base c; cd c; }
part; printf '# My analysis g34a\n' > postProcessing/fsi/2e-09/notes.md; tryf "(a) '#' notes.md in fsi/2e-09" cellBlastFoam -overwrite; kept "My analysis g34a"; cd ..
part; printf 'g34b plain notes\n' > postProcessing/fsi/2e-09/notes.txt; tryf "(b) plain notes.txt in fsi/2e-09" cellBlastFoam -overwrite; kept "g34b plain notes"; cd ..
part; printf '# My analysis g34c\n' > postProcessing/fsi/0/notes.md; tryf "(c) '#' notes.md in fsi/0" cellBlastFoam -overwrite; kept "My analysis g34c"; cd ..
part; printf '# My analysis g34d\n' > postProcessing/solidProbes/2e-09/notes.md; tryf "(d) '#' notes.md in solidProbes/2e-09" cellBlastFoam -overwrite; kept "My analysis g34d"; cd ..
