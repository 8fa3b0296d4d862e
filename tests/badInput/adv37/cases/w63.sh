#!/bin/bash
# w63: pulseStudy run twice at once in the same study case (the point run to 8 ns, the second started 0.5 s after the point's case appears): the second refused naming the first, the first ends well?
. "$(dirname "$0")/../lib.sh"
study; sed -i "s/-endTime 2e-9)/-endTime 8e-9)/" system/pulseStudyDict; pulseStudy -case . > log.1 2>&1 & p=$!; i=0; until ls -d postProcessing/pulseStudy/points/*/case >/dev/null 2>&1 || [ $i -ge 400 ]; do sleep 0.05; i=$((i+1)); done; sleep 0.5; echo "result before the second: $(ls postProcessing/pulseStudy/points/*/result.json 2>/dev/null || echo none)"; try second pulseStudy -case .; wait $p; echo "first rc=$?"; tail -2 log.1 | cut -c1-200
