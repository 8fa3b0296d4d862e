#!/bin/bash
# f09 (class 4, adv46b d40 on the blast preview (cellBlastFoam reads the solid mesh too): the prepared 20 um preview, in
# constant/cell.msh (a) nucleus <-> cytoplasm, (b) membrane <-> cytoplasm swapped by name: each refused before any time
# step naming cell.msh; (c) control, the unchanged mesh: runs (cut at 40 s).
. "$(dirname "$0")/../lib.sh"
blast; cp constant/cell.msh ../msh
sw() { cp ../msh constant/cell.msh; /usr/bin/python3 - "$@" <<'P'
import sys,re; p='constant/cell.msh'; t=open(p).read(); a=sys.argv[1:]
i=t.index('$PhysicalNames'); j=t.index('$EndPhysicalNames'); h=t[i:j]
m={a[k]:a[k+1] for k in range(0,len(a),2)}
h=re.sub(r'"([A-Za-z]+)"', lambda x: '"%s"' % m.get(x.group(1), x.group(1)), h)
open(p,'w').write(t[:i]+h+t[j:])
P
}
st() { echo "   time steps: $(grep -ac '^Time = ' $W/try.log) | times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"; rm -rf postProcessing solid [1-9]*; }
sw nucleus cytoplasm cytoplasm nucleus; tryt 60 "(a) nucleus <-> cytoplasm" cellBlastFoam; st
sw membrane cytoplasm cytoplasm membrane; tryt 60 "(b) membrane <-> cytoplasm" cellBlastFoam; st
cp ../msh constant/cell.msh; tryt 40 "(c) control, unchanged mesh (cut at 40 s)" cellBlastFoam; st
