#!/bin/bash
# CASETIMEOUT=900
# p05b (p05 with its first row mended: (a) ran in the folder the reference run had continued to 3e-9) (new, class 1: a restart with changed time-step controls of system/controlDict, which the input record may not
# cover; system/fvSchemes and fvSolution are recorded): bd restarted to 3e-9 after (a) maxCo 0.2 -> 0.1 (or its value
# halved), (b) maxDeltaT set to 1e-13 s, (c) adjustTimeStep no with deltaT 1e-13; (d) the indentation ik restarted after
# its controlDict's checkpointInterval and fieldWriteInterval were changed. Expected: refused naming the entry, or
# accepted with a note that the continuation is not the run's own time line; accepted without a word = SILENT (low if
# the doc says time-step controls may change on restart). 3e-09/p compared with the uninterrupted bd restart's.
. "$(dirname "$0")/../lib.sh"
bd; rs; rm -f .runLock; cp -a . $W/b0; tryt 300 "(0) the plain restart to 3e-9 (reference)" cellBlastFoam; cp 3e-09/p $W/p.ref 2>/dev/null
back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
cmpP() { [ -f 3e-09/p ] && /usr/bin/python3 -c "
import sys, numpy as np; from neuronFsi import foamField as f
a = np.asarray(f.internalField('3e-09/p')); b = np.asarray(f.internalField(sys.argv[1]))
print('   3e-09/p against the plain restart: largest difference %.3g Pa of %.3g Pa' % (np.abs(a-b).max(), np.abs(b).max()))" $W/p.ref; }
one() { tryt 300 "$1" cellBlastFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | notes: $(grep -a -m2 -i 'maxCo\|maxDeltaT\|deltaT\|changed\|time line\|not the' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300)"; echo "   said: $(msg 3 | cut -c1-250)"; cmpP; }
mc=$(sed -n 's/^maxCo *\([^;]*\);.*/\1/p' system/controlDict); echo "   controlDict maxCo $mc; maxDeltaT $(sed -n 's/^maxDeltaT *\([^;]*\);.*/\1/p' system/controlDict)"
back; sed -i "s/^maxCo .*/maxCo 0.1;/" system/controlDict; one "(a) maxCo $mc -> 0.1"; back
if grep -q '^maxDeltaT' system/controlDict; then sed -i "s/^maxDeltaT .*/maxDeltaT 1e-13;/" system/controlDict; else echo "maxDeltaT 1e-13;" >> system/controlDict; fi; one "(b) maxDeltaT 1e-13"; back
sed -i "s/^adjustTimeStep .*/adjustTimeStep no;/; s/^deltaT .*/deltaT 1e-13;/" system/controlDict; one "(c) adjustTimeStep no, deltaT 1e-13"; back
cd $W; ik; grep -n "checkpointInterval\|fieldWriteInterval" system/controlDict | sed 's/^/   ik controlDict: /'
sed -i '/^checkpointInterval\|^fieldWriteInterval/d' system/controlDict; printf 'checkpointInterval 3;\nfieldWriteInterval 1e-3;\n' >> system/controlDict
tryt 600 "(d) indentation restart with checkpointInterval 3, fieldWriteInterval 1e-3" cellIndentationFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | said: $(msg 3 | cut -c1-250) | notes: $(grep -a -m2 -i 'checkpointInterval\|fieldWriteInterval' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-250)"
