#!/bin/bash
# r31: ind: finished; restart latestTime after removing the last (already run) row
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; python3 - <<'P'
import re; f='constant/indenterProperties'; s=open(f).read(); s=re.sub(r"    \(C1  unload.*?\)\n", "", s); open(f,'w').write(s)
P
cp postProcessing/indentation/force.dat ../f
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A3 "FATAL" log.run | head -5; tail -1 log.run; echo "rc=$rc"; cmp -s ../f postProcessing/indentation/force.dat && echo "force.dat unchanged"
