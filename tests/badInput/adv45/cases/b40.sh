#!/bin/bash
# b40 (class 3, one case reached by several spellings while a run goes): cellIndentationFoam running (finer steps) in $W/ind; a second cellIndentationFoam -case given as $W/ind/, $W/./ind, $W/x/../ind (x exists), a symbolic link $W/l -> $W/ind, and a relative ../ind from $W/x: each refused naming the live run, nothing written; the first run ends rc 0 with consistent results?
. "$(dirname "$0")/../lib.sh"
ind; mkdir -p $W/x; ln -s $W/ind $W/l; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cellIndentationFoam > log.a 2>&1 & p=$!; waitFor 60 test -s .runLock
for c in "$W/ind/" "$W/./ind" "$W/x/../ind" "$W/l"; do tryf "-case $c" cellIndentationFoam -case "$c"; done; cd $W/x; tryf "-case ../ind (from x)" cellIndentationFoam -case ../ind; cd $W/ind
wait $p; echo "   the first run: rc=$?"; forceOk postProcessing/indentation/force.dat; echo "   solid.h5 steps $(h5steps postProcessing/indentation/solid.h5), solid.xmf $(xmfsteps postProcessing/indentation/solid.xmf)"
