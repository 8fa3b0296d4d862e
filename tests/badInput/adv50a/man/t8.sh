. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
pbd; rs; rm -f .runLock; cp -a . ../keep
for v in "processor1 rho 3 -1" "processor1 rho 3 nan" "processor0 rhoE 3 -1e12"; do set -- $v; fset $1/2e-09/$2 internal $3 $4 > /dev/null; mpirun -np 2 cellBlastFoam -parallel -acceptEdited > run.log 2>&1; echo "$v: rc $? | lines naming a cell: $(grep -a -c 'in cell [0-9]' run.log) | 'another rank': $(grep -a -c 'another rank' run.log)"; cd $W; rm -rf pblast; cp -a keep pblast; cd pblast; done
rm -rf $W
