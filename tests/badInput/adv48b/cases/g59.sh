#!/bin/bash
# g59 (class 3, two solidToFoam at once) bd: two solidToFoam solid/solid.h5 started 0.1 s apart: one refused naming the other (lock), the other converts; afterwards constant/solid and the solid times are whole (a third solidToFoam converts the same and foamToVTK -region solid reads them).
. "$(dirname "$0")/../lib.sh"
bd; solidToFoam solid/solid.h5 > ../s1.log 2>&1 & a=$!; sleep 0.1; solidToFoam solid/solid.h5 > ../s2.log 2>&1 & b=$!; wait $a; ra=$?; wait $b; rb=$?
echo "   first rc=$ra $(grep -a -m1 -i 'refus\|in use\|error' ../s1.log | cut -c1-200)"; echo "   second rc=$rb $(grep -a -m1 -i 'refus\|in use\|error' ../s2.log | cut -c1-200)"
tryt 60 "foamToVTK -region solid" foamToVTK -region solid -noFunctionObjects; tail -1 $W/try.log | cut -c1-100; echo "   solid times: $(ls -d [0-9]*/solid | tr '\n' ' ')"
