#!/bin/bash
# g01 (class 1, a $variable): the blast's material set is reached through "$PROJECT_DIR/etc/caseDicts/cellMaterials/table" (an environment variable in an #include). Finished to 2 ns; restart to 3 ns with PROJECT_DIR pointing to (a) a copy of the project's etc/ whose set is the same, (b) a copy whose cytoplasm C10 differs in the 7th digit (another checkout of the project, or the project's set edited by a git pull): (a) continues, (b) refused naming constant/solidProperties?
. "$(dirname "$0")/../lib.sh"
blastDone; grep -n 'include' constant/solidProperties | head -2
mkdir -p $W/projA $W/projB; cp -r $ROOT/etc $W/projA/; cp -r $ROOT/etc $W/projB/
set=$(grep -o 'cellMaterials/[A-Za-z0-9]*' constant/solidProperties | head -1); echo "   set: $set"
/usr/bin/python3 - $W/projB/etc/caseDicts/$set <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read()
i = t.index('cytoplasm'); m = re.compile(r'(C10\s+)([0-9.eE+-]+)').search(t, i)
v = float(m.group(2)); t = t[:m.start(2)] + repr(v * (1 + 3e-7)) + t[m.end(2):]; open(p, 'w').write(t); print('   cytoplasm C10 %s -> %r' % (m.group(2), v * (1 + 3e-7)))
P
cd ..; cp -r blast b; cd blast; latest; blastEnd 3e-9 1e-9
PROJECT_DIR=$W/projA tryf "(a) same set through another PROJECT_DIR" cellBlastFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' ') solid.h5 steps $(h5steps solid/solid.h5)"
cd ../b; latest; blastEnd 3e-9 1e-9; sums > ../s.b
PROJECT_DIR=$W/projB tryf "(b) cytoplasm C10 7th digit through PROJECT_DIR" cellBlastFoam; grep -a -A4 'other inputs' $W/try.log | head -5 | cut -c1-200; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"; nochange ../s.b
