#!/bin/bash
# g59 (class 3, two solidToFoam at once) bd: five trials of two solidToFoam solid/solid.h5 started 0.1 s apart (start and end times recorded): when the two overlap in time, one is refused naming the other (lock) and the other converts; never both converting at once. Afterwards constant/solid and the solid times are whole (foamToVTK -region solid reads them). (Rewritten after its first run, P1: both exited 0 and the case could not tell whether they overlapped.)
. "$(dirname "$0")/../lib.sh"
bd; for k in 1 2 3 4 5; do rm -rf constant/solid system/solid [0-9]*/solid
  ( s=$(date +%s.%N); solidToFoam solid/solid.h5 > ../s1.log 2>&1; echo "$? $s $(date +%s.%N)" > ../r1 ) & a=$!; sleep 0.1
  ( s=$(date +%s.%N); solidToFoam solid/solid.h5 > ../s2.log 2>&1; echo "$? $s $(date +%s.%N)" > ../r2 ) & b=$!; wait $a $b
  read r1 s1 e1 < ../r1; read r2 s2 e2 < ../r2; ov=$(echo "$s2 < $e1" | bc)
  echo "   trial $k: first rc=$r1 ($(echo "$e1 - $s1" | bc | cut -c1-5) s), second rc=$r2 (started $(echo "$s2 - $s1" | bc | cut -c1-5) s after, $([ $ov = 1 ] && echo overlapping || echo after the first ended)) $(grep -a -m1 -i 'in use' ../s2.log ../s1.log | cut -c1-120)"; done
tryt 60 "foamToVTK -region solid" foamToVTK -region solid -noFunctionObjects; tail -1 $W/try.log | cut -c1-100; echo "   solid times: $(ls -d [0-9]*/solid | tr '\n' ' ')"
