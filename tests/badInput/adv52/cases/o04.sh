#!/bin/bash
# CASETIMEOUT=900
# o04 (fix19h's C++ lock judged by the directory's identity through a bind mount, adv51 m04 (d)-(f), varied: the other
# solvers and tools): a solver runs inside an unprivileged user+mount namespace (`unshare -rm`) in the case bind-mounted
# at $W/bind; 4 s later, OUTSIDE by the real path: (a) the smoke indentation (10x finer depth steps) running:
# (a1) a second cellIndentationFoam, (a2) solidToFoam postProcessing/indentation/solid.h5, (a3) cellMesh;
# (b) the waterPulseWall tube (endTime 8e-6) under rhoRiemannFoam: (b1) setRiemannProblem (it writes 0/),
# (b2) a second rhoRiemannFoam, (b3) riemannError; (c) the indentation solver started with `-case $W/bind` from
# elsewhere inside the namespace (an absolute -case), cellIndentationFoam outside. Each: refused rc 1 "in use by", nothing
# of the case changed but the running solver's own outputs; a tool that runs or takes the lock = DATALOSS.
. "$(dirname "$0")/../lib.sh"
nsbg() { mkdir -p $W/bind; printf '%s\n' "mount --bind '$C' '$W/bind' || { echo 'bind failed'; exit 9; }" "cd ${2:-$W/bind} || exit 9" "$1" > $W/ns.sh; unshare -rm bash $W/ns.sh > $W/ns.out 2>&1 & NSP=$!; sleep 4; echo "   lock while the namespace's run goes on: $(head -c 120 $C/.runLock 2>/dev/null | tr '\n' ' ')"; }
nskill() { killIn $W/bind; kill -KILL $NSP 2>/dev/null; wait $NSP 2>/dev/null; sleep 1; killIn $C; killIn $W/bind; sleep 1; echo "   ns out: $(tail -c 300 $W/ns.out | tr '\n' ' ')"; }
watch_() { sums > $W/s0; }
diff_() { echo "   changed under the run (but its own outputs): $(changed $W/s0 | tr ' ' '\n' | grep -v "$1" | grep -v '^$' | tr '\n' ' ' | cut -c1-300)"; }
ind1() { cd $W; rm -rf ind bind; ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; C=$PWD; }
for t in "a1|cellIndentationFoam" "a2|solidToFoam postProcessing/indentation/solid.h5" "a3|cellMesh"; do
  ind1; nsbg "cellIndentationFoam > log.ns 2>&1; echo ns rc \$? >> log.ns"; [ -s .runLock ] || echo "   n/r: no lock when the tool starts"; watch_
  tryt 90 "(${t%%|*}) ${t#*|} outside while cellIndentationFoam runs in the namespace" ${t#*|}; diff_ '^\./postProcessing/indentation/\|^\./\.runLock'
  echo "   still running inside: $([ -e /proc/$NSP ] && echo yes || echo no) | log.ns: $(grep -a -m1 -i 'fatal\|error' log.ns | cut -c1-160)"; nskill; done
wp1() { cd $W; rm -rf wp bind; cp -r $ROOT/tutorials/verification/waterPulseWall wp; cd wp; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1; sed -i 's/^endTime .*/endTime 8e-6;/' system/controlDict; C=$PWD; }
for t in "b1|setRiemannProblem" "b2|rhoRiemannFoam" "b3|riemannError"; do
  wp1; nsbg "rhoRiemannFoam > log.ns 2>&1; echo ns rc \$? >> log.ns"; [ -s .runLock ] || echo "   n/r: no lock when the tool starts"; watch_
  tryt 90 "(${t%%|*}) ${t#*|} outside while rhoRiemannFoam runs in the namespace" ${t#*|}; diff_ '^\./[0-9.e-]*/\|^\./postProcessing/\|^\./\.runLock'
  echo "   still running inside: $([ -e /proc/$NSP ] && echo yes || echo no) | log.ns: $(grep -a -m1 -i 'fatal\|error' log.ns | cut -c1-160)"; nskill; done
ind1; mkdir -p $W/else; nsbg "cellIndentationFoam -case $W/bind > $W/bind/log.ns 2>&1; echo ns rc \$? >> $W/bind/log.ns" $W/else; watch_
tryt 90 "(c) cellIndentationFoam outside while one runs inside with -case \$W/bind from another folder" cellIndentationFoam; diff_ '^\./postProcessing/indentation/\|^\./\.runLock'; nskill
