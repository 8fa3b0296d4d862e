#!/bin/bash
# CASETIMEOUT=900
# f03 (class 4, adv46b d40 on the 3D quarter: tutorials/blast/quarter3D prepared with paperDict's quarter options on one
# rank: -cell 0.7e-6 -lateral 2e-6 -far 10e-6 -inflow 14e-6 -noRun): in constant/cell.msh (a) nucleus <-> cytoplasm,
# (b) membrane <-> cytoplasm swapped by name; cellBlastFoam (cut at 120 s): each refused before any step naming cell.msh;
# never a run with the regions' materials swapped. (The preparation with its planeWave -inflow run took more than 200 s
# under load 19: 600 s allowed, the case 900 s.) (c) control: the unchanged mesh starts (its first time steps).
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/quarter3D" $W/q; cd $W/q; ./Allclean > /dev/null 2>&1
timeout -s KILL 600 ./Allrun -cell 0.7e-6 -lateral 2e-6 -far 10e-6 -inflow 14e-6 -noPlots -noRun > log.prep 2>&1; echo "prepared: rc=$? $(tail -1 log.prep | cut -c1-150)"
cp constant/cell.msh ../msh; sed -n '/\$PhysicalNames/,/\$EndPhysicalNames/p' constant/cell.msh | tr '\n' ' '; echo
sw() { cp ../msh constant/cell.msh; /usr/bin/python3 - "$@" <<'P'
import sys,re; p='constant/cell.msh'; t=open(p).read(); a=sys.argv[1:]
i=t.index('$PhysicalNames'); j=t.index('$EndPhysicalNames'); h=t[i:j]
m={a[k]:a[k+1] for k in range(0,len(a),2)}
h=re.sub(r'"([A-Za-z]+)"', lambda x: '"%s"' % m.get(x.group(1), x.group(1)), h)
open(p,'w').write(t[:i]+h+t[j:])
P
}
st() { echo "   time steps started: $(grep -ac '^Time = ' $W/try.log) | times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"; rm -rf postProcessing solid [1-9]*; }
sw nucleus cytoplasm cytoplasm nucleus; tryt 120 "(a) nucleus <-> cytoplasm" cellBlastFoam; st
sw membrane cytoplasm cytoplasm membrane; tryt 120 "(b) membrane <-> cytoplasm" cellBlastFoam; st
cp ../msh constant/cell.msh; tryt 60 "(c) control, unchanged mesh (cut at 60 s)" cellBlastFoam; st
