#!/bin/bash
# g29 (class 1, the mesh reached by an #include): the indentation's solidProperties mesh{} written as `mesh { #include "meshChoice" }` with constant/meshChoice holding type/file/scale; a fine run SIGKILLed after its first checkpoint; in copies, restart after: (a) meshChoice switched to constant/cellCopy.msh (the same bytes under another name); (b) switched to constant/cellFine.msh (cellMesh with nucleusSize 0.6e-6); (c) constant/cell.msh itself replaced by the finer mesh, meshChoice unchanged: (b), (c) refused naming the mesh; (a) either, with a clear reason
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
/usr/bin/python3 - constant/solidProperties <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); m = re.search(r'\nmesh\s*\{([^{}]*)\}', t)
open('constant/meshChoice', 'w').write(m.group(1).strip() + '\n'); open(p, 'w').write(t[:m.start()] + '\nmesh\n{\n    #include "meshChoice"\n}' + t[m.end():])
P
cat constant/meshChoice | tr -s ' \n' ' '; echo
mkdir -p $W/fine; cp -r system constant $W/fine/; (cd $W/fine; sed -i 's/^nucleusSize .*/nucleusSize 0.6e-6;/' system/cellMeshDict; cellMesh > log.cellMesh 2>&1; echo "   finer mesh: rc $? $(cmp -s constant/cell.msh $W/ind/constant/cell.msh && echo SAME || echo differs)")
cellIndentationFoam > log.first 2>&1 & p=$!; i=0; until [ -f postProcessing/indentation/restart.h5 ] || [ $i -ge 300 ]; do sleep 0.05; i=$((i+1)); done; sleep 0.3; kill -KILL $p; wait $p 2>/dev/null; latest
cd ..; for c in a b c; do cp -r ind $c; done
cd a; cp constant/cell.msh constant/cellCopy.msh; sed -i 's|constant/cell.msh|constant/cellCopy.msh|' constant/meshChoice; tryf "(a) the same mesh under another name" cellIndentationFoam; grep -a -A3 'other inputs' $W/try.log | tail -3 | cut -c1-200
cd ../b; cp $W/fine/constant/cell.msh constant/cellFine.msh; sed -i 's|constant/cell.msh|constant/cellFine.msh|' constant/meshChoice; sums > ../s.b; tryf "(b) meshChoice -> a finer mesh" cellIndentationFoam; grep -a -A3 'other inputs' $W/try.log | tail -3 | cut -c1-200; nochange ../s.b
cd ../c; cp $W/fine/constant/cell.msh constant/cell.msh; sums > ../s.c; tryf "(c) cell.msh replaced by the finer mesh" cellIndentationFoam; grep -a -A3 'other inputs' $W/try.log | tail -3 | cut -c1-200; nochange ../s.c
