#!/bin/bash
# f02 (class 4, adv46b d40 varied: other swaps of the groups' names in constant/cell.msh after cellMesh, the smoke
# indentation): (a) membrane <-> cytoplasm, (b) nucleus <-> membrane, (c) the three rotated (nucleus->cytoplasm->membrane->
# nucleus), (d) the physical tags of the nucleus's and the cytoplasm's surface entities swapped in $Entities (the names
# untouched), (e) the face groups outerSurface <-> axis, (f) both volume groups nucleus and cytoplasm named "cytoplasm".
# Each refused before any step naming cell.msh and the names; never a run (rc 0) with the regions' materials swapped.
. "$(dirname "$0")/../lib.sh"
ind; cp constant/cell.msh ../msh
sw() { cp ../msh constant/cell.msh; /usr/bin/python3 - "$@" <<'P'
import sys,re; p='constant/cell.msh'; t=open(p).read(); a=sys.argv[1:]
i=t.index('$PhysicalNames'); j=t.index('$EndPhysicalNames'); h=t[i:j]
m={a[k]:a[k+1] for k in range(0,len(a),2)}
h=re.sub(r'"([A-Za-z]+)"', lambda x: '"%s"' % m.get(x.group(1), x.group(1)), h)
open(p,'w').write(t[:i]+h+t[j:])
P
sed -n '/\$PhysicalNames/,/\$EndPhysicalNames/p' constant/cell.msh | tail -n +3 | head -6 | tr '\n' ' '; echo; }
res() { echo "   steps: $(grep -vc '^#' postProcessing/indentation/force.dat 2>/dev/null) force rows"; rm -rf postProcessing; }
sw membrane cytoplasm cytoplasm membrane; tryt 90 "(a) membrane <-> cytoplasm" cellIndentationFoam; res
sw nucleus membrane membrane nucleus; tryt 90 "(b) nucleus <-> membrane" cellIndentationFoam; res
sw nucleus cytoplasm cytoplasm membrane membrane nucleus; tryt 90 "(c) rotated" cellIndentationFoam; res
cp ../msh constant/cell.msh; /usr/bin/python3 - <<'P'
p='constant/cell.msh'; L=open(p).read().split('\n'); i=L.index('$Entities'); n=[int(x) for x in L[i+1].split()]
for k in range(i+2+n[0]+n[1], i+2+n[0]+n[1]+n[2]):
    f=L[k].split()
    if f[7]=='1' and f[8] in ('1','2'): f[8]={'1':'2','2':'1'}[f[8]]; L[k]=' '.join(f)+' '
open(p,'w').write('\n'.join(L))
P
echo "   the surface entities' physical tags 1 <-> 2: $(cmp -s ../msh constant/cell.msh && echo NOT changed || echo changed)"; tryt 90 "(d) the entities' physical tags nucleus <-> cytoplasm" cellIndentationFoam; res
sw outerSurface axis axis outerSurface; tryt 90 "(e) outerSurface <-> axis" cellIndentationFoam; res
sw nucleus cytoplasm; tryt 90 "(f) nucleus and cytoplasm both named cytoplasm" cellIndentationFoam; res
