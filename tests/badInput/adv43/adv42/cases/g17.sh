#!/bin/bash
# g17 (class 2+3, the indentation's -overwrite killed at every stage of its start-up): finished smoke indentation; for each delay d a fresh copy, `cellIndentationFoam -overwrite` SIGKILLed d s after its start; then: earlier content lost? (before the new run's first checkpoint none may be), and -overwrite again: force.dat and peaks.dat equal to the original's?
. "$(dirname "$0")/../lib.sh"
indDone; cd ..; mv ind orig
for d in 0.03 0.08 0.15 0.25 0.4 0.6 0.9 1.3 2; do
  rm -rf k; cp -r orig k; cd k; contents > ../before; killAt $d cellIndentationFoam -overwrite > /dev/null
  l=$(lost ../before | wc -l); echo "d=$d: postProcessing/indentation: $(ls -a postProcessing/indentation 2>/dev/null | tr '\n' ' ' | cut -c1-160); aside: $(ls -d postProcessing/.*overw* 2>/dev/null | tr '\n' ' '); earlier contents lost: $l"
  tryf "   -overwrite again" cellIndentationFoam -overwrite; for f in force.dat peaks.dat; do cmp -s postProcessing/indentation/$f ../orig/postProcessing/indentation/$f && echo -n "   $f same" || echo -n "   $f DIFF"; done; echo; cd ..
done
