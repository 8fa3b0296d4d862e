#!/bin/bash
# v09: ind: -overwrite killed at 0.2/0.5/1.0 s (maxDepthIncrement 0.01 um, checkpoints each 0.5 s run time): every earlier content kept somewhere until a commit?
. "$(dirname "$0")/../lib.sh"
indDone; contents > ../before; cp -r . $W/tmpl; cp ../before $W/before
for d in 0.2 0.5 1.0; do
  rm -rf $W/k; cp -r $W/tmpl $W/k; cd $W/k; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
  cellIndentationFoam -overwrite > log.ow 2>&1 & p=$!; sleep $d; kill -KILL $p 2>/dev/null; wait $p 2>/dev/null
  echo "kill at $d s: lost $(lost $W/before | wc -l) contents; $(ls -a postProcessing/indentation | grep -v '^\.$\|^\.\.$' | tr '\n' ' ')"
  done
