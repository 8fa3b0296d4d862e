#!/bin/bash
# h01 (phase C, the new rule: files NAMED like a log but not one): a fresh blast SIGKILLed before its first commit (its function objects' folders recorded by no commit); the user's (a) solidProbes/0/solidProbes.dat replaced by the user's CSV of the same name (no '#' header), (b) fsi/0/coupling.dat holding a Markdown note ("# My analysis"), (c) fluidProbes/0/p holding the user's gnuplot script ("# plot p"), each alone; -overwrite: refused naming the file (its content is not the log's), or removed (the user's content GONE)?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 8e-9 4e-9; cellBlastFoam > log.k 2>&1 & p=$!; waitFor 60 test -f postProcessing/solidProbes/0/solidProbes.dat; waitFor 20 test -f postProcessing/fsi/0/coupling.dat; sleep 0.3; kill -KILL $p; wait $p 2>/dev/null
echo "   killed fresh run: times $(ls -d [0-9]* | tr '\n' ' '); postProcessing: $(cd postProcessing; ls */0 | tr '\n' ' ')"; blastEnd 2e-9 1e-9; cd ..; mv blast k0
part() { rm -rf c; cp -r k0 c; cd c; }
part; printf 'time,value\n0,1\nh01a user csv,2\n' > postProcessing/solidProbes/0/solidProbes.dat; tryf "(a) a CSV named solidProbes.dat" cellBlastFoam -overwrite; kept "h01a user csv"; cd ..
part; printf '# My analysis h01b\n\nnotes\n' > postProcessing/fsi/0/coupling.dat; tryf "(b) a Markdown note named coupling.dat" cellBlastFoam -overwrite; kept "My analysis h01b"; cd ..
part; printf '# plot p h01c\nplot "p" using 1:2\n' > postProcessing/fluidProbes/0/p; tryf "(c) a gnuplot script named p" cellBlastFoam -overwrite; kept "plot p h01c"; cd ..
