#!/bin/bash
# g21 (class 5, solid.h5's readers): finished blast; solid/solid.h5 with one bit flipped at 12 offsets spread over the file (each alone, in a copy); solidToFoam and neuronFsi.solidResults (the reader every script uses): refused, or the same output as the undamaged file? (a different output with exit 0: SILENT)
. "$(dirname "$0")/../lib.sh"
blastDone; solidToFoam solid/solid.h5 > log.s0 2>&1; echo "   solidToFoam on the good file: rc $?"; find 2e-09/solid 1e-09/solid -type f 2>/dev/null | sort | xargs md5sum > ../good.sum
py() { PYTHONPATH=$ROOT/src/python /usr/bin/python3 -c "
import hashlib, numpy as np
from neuronFsi.solidResults import SolidResults
h = hashlib.md5()
with SolidResults('solid/solid.h5') as r:
    for m in ('coordinates', 'connectivity', 'region'):
        h.update(np.ascontiguousarray(r.mesh(m)).tobytes())
    for s in r.steps():
        h.update(repr(r.time(s)).encode())
        for k in sorted(k for k in r.file['steps'][s] if hasattr(r.file['steps'][s][k], 'shape')):
            h.update(np.ascontiguousarray(r.field(s, k)).tobytes())
print(h.hexdigest())" 2>&1 | tail -1 | cut -c1-200; }
echo "   neuronFsi.solidResults on the good file: $(py)"; good=$(py); cd ..; n=$(stat -c %s blast/solid/solid.h5)
for i in 1 2 3 4 5 6 7 8 9 10 11 12; do o=$(( n * i / 13 )); rm -rf d; cp -r blast d; cd d; rm -rf 1e-09/solid 2e-09/solid constant/solid; flip solid/solid.h5 $o
  timeout -s KILL 60 solidToFoam solid/solid.h5 > log.s 2>&1; rc=$?; if [ $rc = 0 ]; then find 2e-09/solid 1e-09/solid -type f 2>/dev/null | sort | xargs md5sum > ../now.sum; cmp -s ../good.sum ../now.sum && s="same output" || s="OUTPUT DIFFERS"; else s=$(grep -a -m1 -A1 'FATAL\|rror' log.s | tr '\n' ' ' | cut -c1-160); fi
  p=$(py); [ "$p" = "$good" ] && p="same values" || p="$p"; echo "byte $o: solidToFoam rc $rc ($s) | solidResults: $p"; cd ..
done
