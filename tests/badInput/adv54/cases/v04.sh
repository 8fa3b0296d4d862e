#!/bin/bash
# CASETIMEOUT=600
# v04 (fix19j row "solidToFoam's marker, -overwrite and the run id", varied: the parallel case, two at once, another
# region name, a link): (a) pbd (2 ranks, times only in processor*/): `solidToFoam solid/solid.h5`: what it wrote and where; (b) bd: two `solidToFoam solid/solid.h5` started 0.05 s apart, then foamToVTK -region solid on the result; (c) bd: `solidToFoam
# solid/solid.h5 -region cell` (another region name) then `-region solid` again, each time's folders; (d) bd with
# constant/solid a link to another case's constant/solid (that case's own converted mesh, its marker in it):
# `solidToFoam solid/solid.h5 -overwrite`. Expected: (a) converted into the times it can name or refused clearly (a
# parallel case's serial times do not exist); (b) the second refused (in use) or both whole; (d) refused (a link leaving
# the case, fix19j), the other case's mesh kept.
. "$(dirname "$0")/../lib.sh"
pbd; tryt 300 "(a) solidToFoam in the 2-rank case" solidToFoam solid/solid.h5; echo "   said: $(say 3 | cut -c1-300) | wrote: $(find . -newer solid/solid.h5 -path '*solid*' -type d | sort | tr '\n' ' ' | cut -c1-300)"
cd $W; bd; solidToFoam solid/solid.h5 > $W/s1.log 2>&1 & sleep 0.05; solidToFoam solid/solid.h5 > $W/s2.log 2>&1; r2=$?; wait $!; r1=$?
echo "   (b) two at once: rc $r1 / $r2 | first: $(grep -a -m1 -A2 'FATAL\|rror' $W/s1.log | tr '\n' ' ' | tr -s ' ' | cut -c1-200) | second: $(grep -a -m1 -A2 'FATAL\|rror' $W/s2.log | tr '\n' ' ' | tr -s ' ' | cut -c1-250)"
echo "   fields: $(ls 1e-09/solid 2e-09/solid 2>/dev/null | tr '\n' ' ' | cut -c1-200)"
tryt 300 "(b2) foamToVTK -region solid -latestTime on the result" foamToVTK -region solid -latestTime; echo "   said: $(say 2 | cut -c1-200)"
tryt 300 "(c) -region cell" solidToFoam solid/solid.h5 -region cell; echo "   said: $(say 2 | cut -c1-250) | regions now: $(ls 2e-09 | tr '\n' ' ') | constant: $(ls constant | tr '\n' ' ')"
tryt 300 "(c2) -region solid again" solidToFoam solid/solid.h5; echo "   said: $(say 2 | cut -c1-250)"
B=$PWD; cd $W; rm -rf other; mkdir other; cp -a $B/constant other/; md5sum other/constant/solid/polyMesh/* > $W/mo; cd $B; rm -rf constant/solid; ln -s $W/other/constant/solid constant/solid
tryt 300 "(d) constant/solid a link to another case's, -overwrite" solidToFoam solid/solid.h5 -overwrite; echo "   said: $(say 2 | cut -c1-300) | other's mesh: $(md5sum -c $W/mo 2>&1 | grep -c ': OK') of $(wc -l < $W/mo) kept"
