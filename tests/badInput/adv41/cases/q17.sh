#!/bin/bash
# q17: the -overwrite guard's exemptions ("in a folder no commit records, a file that is neither empty, nor an OpenFOAM file, nor begins with a log's '#' header"): user files that look like the run's: (a) a Markdown notes.md ("# My analysis") in a time-named folder postProcessing/fsi/5e-09/; (b) the same in postProcessing/fsi/0/ (a recorded folder); (c) an empty TODO and a FoamFile-headed dictionary of the user's in postProcessing/solidProbes/0/; (d) notes.md in the segment of a restart SIGKILLed before its first commit; each alone, -overwrite: kept or refused? (e) as (d) with a plain notes.txt; (f) a fresh run killed before its first commit, notes.md in solidProbes/0/
. "$(dirname "$0")/../lib.sh"
md() { printf '# My analysis of %s\n\nThe peak at 1.2 ns is real; see plot.\n' "$1"; }
blastDone; cd ..; cp -r blast base; cd blast
part() { rm -rf ../blast; cp -r ../base ../blast; cd ../blast; }
part; mkdir -p postProcessing/fsi/5e-09; md a > postProcessing/fsi/5e-09/notes.md; tryf "(a) -overwrite" cellBlastFoam -overwrite; kept "analysis of a"
part; md b > postProcessing/fsi/0/notes.md; tryf "(b) -overwrite" cellBlastFoam -overwrite; kept "analysis of b"
part; : > postProcessing/solidProbes/0/TODO; printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class dictionary;\n    object myLimits;\n}\n// c: my plot limits\nyMax 1e8;\n' > postProcessing/solidProbes/0/myLimits
tryf "(c) -overwrite" cellBlastFoam -overwrite; kept "c: my plot limits"; [ -e postProcessing/solidProbes/0/TODO ] && echo "   TODO kept" || echo "   TODO GONE"
cd $W; rm -rf blast; blast
blastEnd 1e-9 1e-9; cellBlastFoam > log.1 2>&1; latest; blastEnd 8e-9 1e-9; sed -i 's/^writeInterval .*/writeInterval 4e-9;/' system/controlDict.allrun
cellBlastFoam > log.2 2>&1 & p=$!; waitFor 60 test -d postProcessing/fsi/1e-09; sleep 0.3; kill -KILL $p; wait $p 2>/dev/null; echo "   (d) killed restart: times $(ls -d [0-9]* | tr '\n' ' '); fsi segments: $(ls postProcessing/fsi | tr '\n' ' ')"
md d > postProcessing/fsi/1e-09/notes.md; sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; blastEnd 2e-9 1e-9
cd $W; rm -rf killed; cp -r blast killed; cd blast
tryf "(d) -overwrite" cellBlastFoam -overwrite; kept "analysis of d"
cd $W/killed; rm postProcessing/fsi/1e-09/notes.md; echo "e: my plain notes" > postProcessing/fsi/1e-09/notes.txt; tryf "(e) the same with a notes.txt not beginning with '#'" cellBlastFoam -overwrite; kept "e: my plain notes"
# (f) a FRESH run SIGKILLed before its first commit (the restart's documented way out is -overwrite); the user's notes.md ("# ...") in postProcessing/solidProbes/0/
cd $W; rm -rf blast; blast; blastEnd 8e-9 4e-9; cellBlastFoam > log.k 2>&1 & p=$!; waitFor 60 test -f postProcessing/solidProbes/0/solidProbes.dat; sleep 0.3; kill -KILL $p; wait $p 2>/dev/null; echo "   (f) killed fresh run: times $(ls -d [0-9]* | tr '\n' ' ')"
md f > postProcessing/solidProbes/0/notes.md; blastEnd 2e-9 1e-9; tryf "(f) -overwrite" cellBlastFoam -overwrite; kept "analysis of f"
