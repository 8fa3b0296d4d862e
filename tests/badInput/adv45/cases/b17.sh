#!/bin/bash
# b17 (class 2, pulseStudy interrupted at its very start): SIGTERM to the study's group 0.3 s and 1.5 s after its start (copying its base), then the study again to its end: it completes (one point, its table), nothing of the interrupted starts left that makes it fail or changes its result?
. "$(dirname "$0")/../lib.sh"
study
for s in 0.3 1.5; do setsid pulseStudy -case . > ../log.t$s 2>&1 & p=$!; sleep $s; kill -TERM -- -$p 2>/dev/null; wait $p; echo "   SIGTERM at $s s: rc=$?; pulseStudy/: $(ls -a postProcessing/pulseStudy 2>/dev/null | tr '\n' ' ') points: $(ls -a postProcessing/pulseStudy/points 2>/dev/null | tr '\n' ' ')"; done
run 250 pulseStudy -case . > ../log.s 2>&1; grep -a -m4 -i 'error\|refus\|done\|interrupted' ../log.s | cut -c1-240; echo "   table: $(wc -l < postProcessing/pulseStudy/table.csv 2>/dev/null) lines; points: $(ls postProcessing/pulseStudy/points | tr '\n' ' ')"
