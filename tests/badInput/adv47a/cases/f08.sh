#!/bin/bash
# f08 (class 5, f07's scope: the conservative field rho of the restart time damaged (64 bytes zeroed) under an intact commit
# marker, other solvers and layouts): (a) the sod tube (rhoRiemannFoam) finished, endTime 1.5x, each field file of its
# last time that exists of rho, rhoU, rhoE, p, T damaged in turn; (b) the preview on 2 ranks (pblastDone), startFrom
# latestTime, endTime 3e-9, processor1/2e-09/rho damaged. Each refused naming the file, never a sigFpe or a run from it.
. "$(dirname "$0")/../lib.sh"
dmg() { /usr/bin/python3 - "$1" <<'P'
import sys; f=sys.argv[1]; s=bytearray(open(f,'rb').read()); k=s.find(b'internalField'); k=s.find(b'(', k)+200; s[k:k+64]=b'\0'*64; open(f,'wb').write(s)
P
}
sodDone; t=$(ls -d [0-9]* | sort -g | tail -1); e=$(/usr/bin/python3 -c "print(repr($t*1.5))"); echo "sod last time $t: $(ls $t | tr '\n' ' ')"
sed -i "s/^endTime .*/endTime $e;/; s/^writeInterval .*/writeInterval $e;/" system/controlDict; cp -a . ../sodKeep
for f in rho rhoU rhoE p T; do [ -f $t/$f ] || continue; dmg $t/$f; tryt 60 "(a) sod $t/$f damaged" rhoRiemannFoam; echo "   crashed: $(grep -ac sigHandler $W/try.log) | times: $(ls -d [0-9]* | tr '\n' ' ')"; cd $W; rm -rf sod; cp -a sodKeep sod; cd sod; done
pblastDone; latest; blastEnd 3e-9 1e-9; dmg processor1/2e-09/rho; tryt 120 "(b) 2 ranks, processor1/2e-09/rho damaged" mpirun -np 2 cellBlastFoam -parallel; echo "   crashed: $(grep -ac sigHandler $W/try.log) | times: $(ls -d processor1/[0-9]* | tr '\n' ' ')"
