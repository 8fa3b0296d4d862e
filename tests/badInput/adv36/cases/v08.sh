#!/bin/bash
# v08: blast: -overwrite killed at 0.3/0.8/1.6/2.6/3.6 s (endTime 2e-8, writes every 1e-8): after each kill, every earlier content still somewhere (or a new commit made)?
. "$(dirname "$0")/../lib.sh"
blastDone; contents > ../before; cp -r . $W/tmpl; cp ../before $W/before
for d in 0.3 0.8 1.6 2.6 3.6; do
  rm -rf $W/k; cp -r $W/tmpl $W/k; cd $W/k; blastEnd 2e-8 1e-8
  cellBlastFoam -overwrite > log.ow 2>&1 & p=$!; sleep $d; kill -KILL $p 2>/dev/null; wait $p 2>/dev/null
  n=$(lost $W/before | wc -l); c=$(ls -d 1e-08 2>/dev/null); echo "kill at $d s: lost $n contents; new commit: ${c:-none}; $(ls -a | grep overwritten | tr '\n' ' ')"
  done
