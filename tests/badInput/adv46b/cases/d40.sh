#!/bin/bash
# d40 (class 4, cell.msh physical groups edited after cellMesh, indentation, 60 s): (a) the face group outerSurface renamed outerSurfaceX; (b) an extra unused physical group added (accepted); (c) the volume groups nucleus and cytoplasm swapped by name: (a) and (c) refused naming the group, (b) runs.
. "$(dirname "$0")/../lib.sh"
ind; cp constant/cell.msh ../msh; sed -n "/\$PhysicalNames/,/\$EndPhysicalNames/p" constant/cell.msh
sed -i "s/\"outerSurface\"/\"outerSurfaceX\"/" constant/cell.msh; tryt 60 "(a) outerSurface renamed" cellIndentationFoam; rm -rf postProcessing
cp ../msh constant/cell.msh; python3 - constant/cell.msh <<P
import sys,re; p=sys.argv[1]; t=open(p).read(); m=re.search(r"\\\$PhysicalNames\n(\d+)\n", t); n=int(m.group(1))
t=t[:m.start(1)]+str(n+1)+t[m.end(1):]; i=t.index("\$EndPhysicalNames"); t=t[:i]+"2 999 \"mySpareGroup\"\n"+t[i:]; open(p,"w").write(t)
P
tryt 60 "(b) extra unused group" cellIndentationFoam; rm -rf postProcessing
cp ../msh constant/cell.msh; sed -i "s/\"nucleus\"/\"TMPX\"/; s/\"cytoplasm\"/\"nucleus\"/; s/\"TMPX\"/\"cytoplasm\"/" constant/cell.msh; sed -n "/\$PhysicalNames/,/\$EndPhysicalNames/p" constant/cell.msh | tr "\n" " "; echo; tryt 60 "(c) nucleus and cytoplasm swapped" cellIndentationFoam; rm -rf postProcessing
