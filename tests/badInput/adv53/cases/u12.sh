#!/bin/bash
# CASETIMEOUT=900
# u12 (fix19i row "the bench/blast analysis scripts on a folder that is no case" (script.guard in 13 scripts), varied:
# the other analysis scripts of bench/blast and bench/blast/analysis, which neither p18 nor fix19i ran): each of
# analysis/{axisev,firstpass,interfaceTop,late,layer,patchProfile,regions,ringvm,vmtop,vtkpatch}.py and
# {ballLadder,elementChain1D,knobMatrix,layeredSplit,planeWaveCellSummary,sceneAgainstPreview,solidProbeLadder,
# solidVariantTable,strainSplit,subcycles,transparentLadder,waterProbeHistory,compareRuns}.py on (a) an empty folder,
# (b) the finished 2-ns preview bd, (c) bd with postProcessing/fsi/0/coupling.dat zeroed (NUL bytes). Each: one line
# naming what is missing or damaged (rc != 0), or a result; a Python traceback = CRASH (low); a measure from the zeroed
# file without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
B=$ROOT/bench/blast; mkdir -p $W/empty; bd; C=$PWD; cp -a $C $W/z; nul $W/z/postProcessing/fsi/0/coupling.dat
run1() { local l=$1; shift; tryt 60 "$l" /usr/bin/python3 "$@"; echo "   traceback: $(grep -a -c Traceback $W/try.log) $(grep -a -A30 Traceback $W/try.log | grep -a -v '^ ' | grep -a -v Traceback | head -1 | cut -c1-120) | last: $(grep -a -v '^ *$' $W/try.log | tail -1 | cut -c1-160)"; }
for s in analysis/axisev analysis/firstpass analysis/interfaceTop analysis/late analysis/layer analysis/patchProfile analysis/regions analysis/ringvm analysis/vmtop analysis/vtkpatch ballLadder elementChain1D knobMatrix layeredSplit planeWaveCellSummary sceneAgainstPreview solidProbeLadder solidVariantTable strainSplit subcycles transparentLadder waterProbeHistory; do
  run1 "(a) $s.py on an empty folder" $B/$s.py $W/empty; run1 "(b) $s.py on bd" $B/$s.py $C; run1 "(c) $s.py on bd with coupling.dat zeroed" $B/$s.py $W/z; done
run1 "(b) compareRuns.py bd bd" $B/compareRuns.py $C $C; run1 "(c) compareRuns.py bd, bd with coupling.dat zeroed" $B/compareRuns.py $C $W/z
