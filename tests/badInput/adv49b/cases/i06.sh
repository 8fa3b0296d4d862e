#!/bin/bash
# i06 (class 2, an Allrun re-run with the other meshType): a preview prepared with `Allrun $PREV -noRun` (unstructured by
# default), then (a) `Allrun $PREV -noRun -meshType structured` over it: refused naming -meshType with both values and
# ./Allclean, constant/cell.msh unchanged; (b) `-meshType unstructured` given explicitly (the default's value): accepted or
# refused, but cell.msh unchanged in content either way; (c) after ./Allclean the structured preparation runs and writes a
# structured cell (the log says structured).
. "$(dirname "$0")/../lib.sh"
prev; run 300 ./Allrun $PREV -endTime 1e-9 -noRun > ../log.p1 2>&1; md5sum constant/cell.msh > ../m0; sums > ../s0
tryt 300 "(a) -meshType structured over an unstructured preparation" ./Allrun $PREV -endTime 1e-9 -noRun -meshType structured; echo "   changed: $(changed ../s0)"; md5sum -c ../m0 | sed 's/^/   /'
tryt 300 "(b) -meshType unstructured (the default, explicit)" ./Allrun $PREV -endTime 1e-9 -noRun -meshType unstructured; echo "   changed: $(changed ../s0)"; md5sum -c ../m0 | sed 's/^/   /'
./Allclean > /dev/null 2>&1; tryt 300 "(c) after Allclean, structured" ./Allrun $PREV -endTime 1e-9 -noRun -meshType structured; echo "   cellMesh log: $(grep -a -i -m2 'structured' log.cellMesh | cut -c1-160 | tr '\n' '|')"
