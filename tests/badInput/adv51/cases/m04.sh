#!/bin/bash
# CASETIMEOUT=900
# m04 (fix19g's lock by the directory's identity, adv50a k10 (d), Python side fixed, varied): the finished preview bd ($C,
# its Allclean and Allrun copied in), a restart to 4e-8 running through a bind mount at $W/bind inside an unprivileged
# user+mount namespace (`unshare -rm`, as a rootless container binds a folder); 4 s later, OUTSIDE by the real path:
# (a) $C/Allclean, (b) `planeWave -case $C` (Python tool with the lock), (c) $C/Allrun -noRun (the Allrun's lock),
# (d) `solidToFoam solid/solid.h5` (C++ tool with the lock), (e) a second cellBlastFoam (C++: the open row of fix19g),
# (f) cellMesh (C++). Then the reverse for the C++ side: (g) the solver outside in $C, `solidToFoam` inside the namespace;
# (h) a hard link of the case's directory is impossible: a second bind of a subfolder (constant/ bound elsewhere) ignored.
# Each: refused naming the running solver, nothing removed or written; the solver's run ends rc 0 (or is reported).
. "$(dirname "$0")/../lib.sh"
fresh() { cd $W; rm -rf blast bind; mkdir -p bind; bd; cp "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" "$ROOT/tutorials/blast/axisymmetricPreview/Allrun" .; C=$PWD; latest; blastEnd 4e-8 1e-9; rm -f .runLock; }
state() { echo "   case: $(cd $C; ls -d [0-9]* solid constant/cell.msh 2>/dev/null | tr '\n' ' ')| markers: $(cd $C; ls [0-9]*/.writeCommitted 2>/dev/null | wc -l) | lock: $(head -c 160 $C/.runLock 2>/dev/null | tr '\n' ' ')"; }
nsbg() { printf '%s\n' "mount --bind '$C' '$W/bind' || { echo 'bind failed'; exit 9; }" "cd '$W/bind' || exit 9" "$1" > $W/ns.sh; (unshare -rm bash $W/ns.sh > $W/ns.out 2>&1 &); sleep 4; echo "   lock in the namespace's run: $(head -c 160 $C/.runLock 2>/dev/null | tr '\n' ' ')"; }
nswait() { local i; for i in $(seq 90); do pgrep -f "bash $W/ns.sh" > /dev/null || break; sleep 2; done; pgrep -f "bash $W/ns.sh" > /dev/null && { echo "   ns run still going after 180 s: killed"; for p in $(pgrep -f "bash $W/ns.sh"); do kill -KILL $p; done; killIn $W/bind; killIn $C; }; echo "   ns solver: $(grep -a 'ns rc' $C/log.ns 2>/dev/null) $(grep -a -m1 -i 'FATAL\|error' $C/log.ns 2>/dev/null | cut -c1-200)"; }
one() { fresh; nsbg "cellBlastFoam > log.ns 2>&1; echo ns rc \$? >> log.ns"; cd $C; sums > $W/s0; [ -s $C/.runLock ] || echo "   n/r: no lock when the tool starts"; local l=$1; shift; eval "tryt 90 \"\$l\" $*"; echo "   changed under the run: $(changed $W/s0 | tr ' ' '\n' | grep -v '^\./[0-9]e-09/\|^\./solid/\|^\./postProcessing/\|^$' | tr '\n' ' ' | cut -c1-200)"; state; nswait; state; }
one "(a) \$C/Allclean outside while cellBlastFoam runs in the namespace" '$C/Allclean'
one "(b) planeWave -case \$C outside" planeWave -case '$C'
one "(c) \$C/Allrun -noRun outside" '$C/Allrun' -noRun
one "(d) solidToFoam solid/solid.h5 outside" solidToFoam solid/solid.h5
one "(e) a second cellBlastFoam outside" cellBlastFoam
one "(f) cellMesh outside" cellMesh
fresh; rm -rf constant/solid; (cellBlastFoam > log.bg 2>&1; echo "bg rc $?" >> log.bg) & bp=$!; sleep 4; echo "   lock: $(head -c 160 $C/.runLock | tr '\n' ' ')"
printf '%s\n' "mount --bind '$C' '$W/bind' || exit 9" "cd '$W/bind' || exit 9" "solidToFoam solid/solid.h5; echo ns rc \$?" > $W/ns.sh; tryt 90 "(g) solidToFoam in the namespace while cellBlastFoam runs outside" unshare -rm bash $W/ns.sh; echo "   ns: $(tail -2 $W/try.log | tr '\n' ' ' | cut -c1-250)"; wait $bp; echo "   outside solver: $(tail -1 $C/log.bg)"; state
