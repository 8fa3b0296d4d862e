#!/bin/bash
# g02 (class 1, a $variable, indentation): the indentation's material set is reached through $PROJECT_DIR in an #include. A run SIGKILLed after its first checkpoint; restart with PROJECT_DIR pointing to (a) a copy of etc/ with the same set, (b) a copy whose nucleus mu1 differs in the 7th digit: (a) continues with force.dat equal to an uninterrupted run's, (b) refused naming the region?
. "$(dirname "$0")/../lib.sh"
indKilled 1; cd ..; cp -r ind k2; cd ind
mkdir -p $W/projA $W/projB; cp -r $ROOT/etc $W/projA/; cp -r $ROOT/etc $W/projB/
set=$(grep -o 'cellMaterials/[A-Za-z0-9]*' constant/solidProperties | head -1); echo "   set: $set"
/usr/bin/python3 - $W/projB/etc/caseDicts/$set <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read()
i = t.index('nucleus'); m = re.compile(r'(mu1\s+)([0-9.eE+-]+)').search(t, i)
v = float(m.group(2)); t = t[:m.start(2)] + repr(v * (1 + 3e-7)) + t[m.end(2):]; open(p, 'w').write(t); print('   nucleus mu1 %s -> %r' % (m.group(2), v * (1 + 3e-7)))
P
PROJECT_DIR=$W/projA tryf "(a) same set, other PROJECT_DIR" cellIndentationFoam; forceOk postProcessing/indentation/force.dat
mkdir -p $W/u; cp -r $ADV/indBase/{system,constant} $W/u/; (cd $W/u; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cellIndentationFoam > log.u 2>&1); cmp -s postProcessing/indentation/force.dat $W/u/postProcessing/indentation/force.dat && echo "   force.dat equal to the uninterrupted run's" || echo "   force.dat DIFFERS from the uninterrupted run's"
cd ../k2; sums > ../s.k; PROJECT_DIR=$W/projB tryf "(b) nucleus mu1 7th digit through PROJECT_DIR" cellIndentationFoam; grep -a -A3 'other inputs' $W/try.log | head -4 | cut -c1-200; nochange ../s.k
