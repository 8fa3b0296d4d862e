#!/bin/bash
# CASETIMEOUT=300
# u06 (fix19i row "the bench scripts' own sub-folders" (pulseLayerMotion.sh, structuredLadderRuns.sh, run.py,
# memoryPerCell.py through outputFolder), varied: the bench scripts of bench/ciTime that fix19h/fix19i did not list):
# (a) bench/ciTime/corpusHarness.sh OLD NEW OUT with OUT a user's folder holding notes.txt and results/data.txt;
# (b) bench/ciTime/corpusCost.sh OLD NEW OUT with a user's OUT/bases/notes.txt. OLD and NEW are stand-in checkouts (their
# etc/bashrc empty, their tests/badInput/runCorpus.sh an `echo`: the harness runs, no corpus). Expected: refused naming
# what OUT holds, nothing removed (docs/reliability.md: every benchmark's script that replaced its output folder goes
# through neuronFsi.scratch.outputFolder); the user's files removed = DATALOSS.
. "$(dirname "$0")/../lib.sh"
for s in o n; do mkdir -p $W/$s/etc $W/$s/tutorials $W/$s/tests/lib $W/$s/tests/verification $W/$s/tests/fsi $W/$s/tests/badInput; : > $W/$s/etc/bashrc
  printf '#!/bin/bash\necho "stand-in runCorpus.sh $*"\n' > $W/$s/tests/badInput/runCorpus.sh; : > $W/$s/tests/badInput/cellMeshDict; printf 'row | a | b | c | d | e\n' > $W/$s/tests/badInput/corpus; done
cd $W; mark out/notes.txt; mark out/results/data.txt
tryt 60 "(a) corpusHarness.sh o n out (out: a user's folder)" bash $ROOT/bench/ciTime/corpusHarness.sh $W/o $W/n out; echo "   said: $(head -3 $W/try.log | tr '\n' '|' | cut -c1-250)"; kept_ out/notes.txt; kept_ out/results/data.txt
cd $W; rm -rf out; mark out2/bases/notes.txt
tryt 60 "(b) corpusCost.sh o n out2 (out2/bases: a user's folder)" bash $ROOT/bench/ciTime/corpusCost.sh $W/o $W/n out2; echo "   said: $(head -3 $W/try.log | tr '\n' '|' | cut -c1-250)"; kept_ out2/bases/notes.txt
