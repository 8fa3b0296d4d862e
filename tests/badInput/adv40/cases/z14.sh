#!/bin/bash
# z14: indentation Allrun whose solver fails at its start (a protocol row with motion 'lod'): the Allrun's exit and marks; the row fixed and ./Allrun again: the solver runs (not skipped as already run), exit 0, and peaks.dat equals a clean Allrun's?
. "$(dirname "$0")/../lib.sh"
indAllrun; cp -r $W/ia $W/ref; sed -i '0,/(C1  load/s/(C1  load/(C1  lod/' constant/indenterProperties; grep -c ' lod ' constant/indenterProperties
run 200 ./Allrun > ../log.a1 2>&1; echo "   first Allrun: $(grep -a -i -m2 'error\|refus\|fail' ../log.a1 | cut -c1-200 | tr '\n' '|')"; echo "   logs: $(ls log.* | tr '\n' ' ')"
sed -i 's/(C1  lod /(C1  load /' constant/indenterProperties
run 200 ./Allrun > ../log.a2 2>&1; echo "   second Allrun: $(grep -a -i -m3 'already\|error\|refus\|fail' ../log.a2 | cut -c1-200 | tr '\n' '|')"; echo "   logs: $(ls log.* | tr '\n' ' ')"
(cd $W/ref && run 200 ./Allrun > ../log.ref 2>&1)
cmp postProcessing/indentation/peaks.dat $W/ref/postProcessing/indentation/peaks.dat && echo "peaks.dat identical to the clean Allrun's" || echo "peaks.dat DIFFERS from the clean Allrun's"
