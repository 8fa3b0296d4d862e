#!/bin/bash
# o03b (adv35 o03 redone: in this pass's run (load 15-19) the SIGKILL at 0.5 s landed before -overwrite moved anything, so
# the earlier results were simply intact): the same case with the kill as soon as -overwrite has moved the earlier
# results aside (waitFor .force.dat.overwritten, at most 60 s): the earlier results must still be there (aside), and a
# later restart or -overwrite must not lose them silently; then the same with the kill 1 s after that
. "$(dirname "$0")/../lib.sh"
indDone; cp -r postProcessing ../pp.before; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cp -a . ../o0
for extra in 0 1; do
  cellIndentationFoam -overwrite > log.new 2>&1 & p=$!; waitFor 60 test -f postProcessing/indentation/.force.dat.overwritten && echo "aside seen"; sleep $extra; kill -9 $p; wait $p; echo "(+$extra s) killed rc=$?"
  ls -a postProcessing/indentation | tr '\n' ' '; echo; wc -l postProcessing/indentation/*.dat postProcessing/indentation/.*.dat 2>/dev/null | tr '\n' ' '; echo
  cellIndentationFoam > log.again 2>&1; echo "   then a plain start: rc=$? | $(grep -a -m1 -A2 'FATAL' log.again | tail -2 | tr '\n' ' ' | cut -c1-300)"; kept "$(head -c 60 ../pp.before/indentation/force.dat | tail -c 30)" 2>/dev/null | head -2
  cd $W; rm -rf ind; cp -a o0 ind; cd ind; done
