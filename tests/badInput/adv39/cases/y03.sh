#!/bin/bash
# y03: preview Allrun run to its end; then log.blockMesh's status mark removed and its "End" line deleted (a step whose log has no End, no marks); ./Allrun again: blockMesh re-run saying why; and then? (the mesh rewritten under the results, solver skipped?)
. "$(dirname "$0")/../lib.sh"
prev; run 200 ./Allrun $PREV -endTime 2e-9 > ../log.a1 2>&1; echo "first: times $(ls -d [1-9]* | tr '\n' ' '); marks $(ls log.*.status | tr '\n' ' ')"
snap ../before; rm -f log.blockMesh.status log.blockMesh.running; sed -i '/^End/d' log.blockMesh
run 200 ./Allrun $PREV -endTime 2e-9 > ../log.a2 2>&1; echo "second Allrun: $(grep -a -i "already\|error\|refus\|stopped\|again\|blockMesh" ../log.a2 | head -4 | cut -c1-200 | tr '\n' '|')"
echo "files changed/lost since the first run: $(gone ../before | head -8 | tr '\n' ' ')"
