#!/bin/bash
# i41 (class 1/SILENT, calibrateCell stopped and run again with a changed dictionary in the same -work folder): the
# calibration tutorial shortened (protocol ((A load 0.3e-6 1.41e-6) (B hold 0 15)), target F_B only, maxIterations 2,
# nProcs 1), run with -work $W/work -keep, SIGTERMed after its first evaluation line; then meshSizeFactor 1.2 (since P1b: 2.0 made gmsh fail in P1) and run again
# with the same -work: refused (the folder holds another run's files) or run from scratch: its first evaluation's |r| equals
# that of a fresh run with 1.2 in an empty -work (C), never that of the 1.4 mesh (a reused mesh or forward run: SILENT).
. "$(dirname "$0")/../lib.sh"
cal; /usr/bin/python3 - <<'P'
import re; p = 'system/calibrationDict'; t = open(p).read()
t = re.sub(r'\nmaxIterations\s+[^;]*;', '\nmaxIterations 2;', t); t = re.sub(r'\nnProcs\s+[^;]*;', '\nnProcs 1;', t)
i = t.index('targets'); j = t.index('{', i); k = j; d = 0
while True:
    k += 1; d += {'{': 1, '}': -1}.get(t[k], 0)
    if d < 0: break
t = t[:j] + '{\n    F_B { peak endB; value 0.3e-9; }\n' + t[k:]
t = t.replace('\ntargets', '\nprotocol ( (A load 0.3e-6 1.41e-6) (B hold 0 15) );\ntargets', 1); open(p, 'w').write(t)
P
grep -a -n 'protocol\|F_B\|maxIter\|nProcs\|meshSizeFactor' system/calibrationDict | head -8 | sed 's/^/   /'; cp system/calibrationDict ../d0
calibrateCell -work $W/work -keep > ../log.A 2>&1 & p=$!; waitFor 600 grep -q -i '|r|' ../log.A; sleep 0.5; kill -TERM $p; wait $p; echo "   A exit $? | first evaluation: $(grep -a -m1 -i '|r|' ../log.A | cut -c1-200)"; echo "   work: $(ls $W/work 2>/dev/null | tr '\n' ' ' | cut -c1-300)"
sete system/calibrationDict meshSizeFactor 1.2; tryt 900 "B: meshSizeFactor 1.2, same -work" calibrateCell -work $W/work -keep; cp $W/try.log ../log.B; echo "   B first evaluation: $(grep -a -m1 -i '|r|' ../log.B | cut -c1-200)"
tryt 900 "C: meshSizeFactor 1.2, fresh -work" calibrateCell -work $W/work2 -keep; echo "   C first evaluation: $(grep -a -m1 -i '|r|' $W/try.log | cut -c1-200)"
