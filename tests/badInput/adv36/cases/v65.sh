#!/bin/bash
# v65: ind: -overwrite SIGKILLed before its first checkpoint, then the .<name>.overwritten files renamed back: does the restart continue the earlier results?
. "$(dirname "$0")/../lib.sh"
indDone; contents > ../before; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
cellIndentationFoam -overwrite > log.ow 2>&1 & p=$!; sleep 0.7; kill -KILL $p; wait $p 2>/dev/null; cd postProcessing/indentation; ls -a | tr '\n' ' '; echo
for f in .*.overwritten; do b=${f#.}; mv -f "$f" "${b%.overwritten}"; done; cd ../..; echo "lost after the rename: $(lost ../before | wc -l)"
sed -i 's/maxDepthIncrement 0.01e-6/maxDepthIncrement 0.1e-6/' constant/indenterProperties; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i 's/(C1  unload  10e-6   0.5e-6)/&\n    (C2  hold    0       0.2)/' constant/indenterProperties
cellIndentationFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A5 FATAL log.r | head -6 | cut -c1-300; grep -a -i "continu\|restart" log.r | head -2
