#!/bin/bash
# b23 (class 4, paperFigures with its postProcessing/runs read-only): (a) postProcessing/runs a read-only folder (bind mount); paperFigures (SIGTERMed after 40 s if it runs): an error naming the folder, no traceback, nothing else written; (b) -results naming a missing folder, a file, a folder with unicode (empty): refused naming the option (with -noRun)?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/paper" $W/paper; cd $W/paper; mkdir -p postProcessing/runs; ro postProcessing/runs
setsid paperFigures > ../log.a 2>&1 & p=$!; waitFor 40 bash -c "! kill -0 $p"; kill -TERM -- -$p 2>/dev/null; wait $p; echo "(a) rc=$? | $(grep -a -m2 -i 'error\|refus\|Traceback\|read-only' ../log.a | cut -c1-240 | tr '\n' '|')"; umount postProcessing/runs
mkdir -p "$W/tütorials"; echo x > $W/afile
for r in $W/none $W/afile "$W/tütorials"; do tryf "(b) -results $r" paperFigures -noRun -results "$r"; done; echo "   written: $(ls -a postProcessing | tr '\n' ' ')"
