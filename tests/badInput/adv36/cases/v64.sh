#!/bin/bash
# v64: blast: -overwrite SIGKILLed before its first write, then every .<name>.overwritten renamed back in every folder (a complete recovery): does the restart continue the earlier run exactly?
. "$(dirname "$0")/../lib.sh"
blastDone; contents > ../before; blastEnd 2e-8 1e-8
cellBlastFoam -overwrite > log.ow 2>&1 & p=$!; sleep 1.5; kill -KILL $p; wait $p 2>/dev/null; echo "lost after kill: $(lost ../before | wc -l)"
find . -name '.*.overwritten*' | sort
find . -depth -name '.*.overwritten' | while read f; do d=$(dirname $f); b=$(basename $f); b=${b#.}; rm -rf "$d/${b%.overwritten}"; mv "$f" "$d/${b%.overwritten}"; done
echo "lost after the full rename: $(lost ../before | wc -l)"; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A5 FATAL log.r | head -6 | cut -c1-300
