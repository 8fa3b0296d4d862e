#!/bin/bash
# z35: z11 on a restarted run: blast to 1 ns, restarted to 2 ns (function-object segments postProcessing/*/0 and */1e-09); a user's notes.txt in postProcessing/fsi/1e-09/; `cellBlastFoam -overwrite` from 0: the note kept (or the run refused naming it)?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 1e-9 1e-9; cellBlastFoam > log.1 2>&1; latest; blastEnd 2e-9 1e-9; cellBlastFoam > log.2 2>&1; ls postProcessing/fsi | tr '\n' ' '; echo
echo "my notes on the restart" > postProcessing/fsi/1e-09/notes.txt; sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict
tryf "-overwrite" cellBlastFoam -overwrite; echo "   notes.txt: $(grep -rl 'my notes on the restart' . 2>/dev/null | tr '\n' ' ')"; [ -n "$(grep -rl 'my notes on the restart' .)" ] || echo "   notes.txt GONE"
