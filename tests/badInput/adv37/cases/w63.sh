#!/bin/bash
# w63: pulseStudy run twice at once in the same study case: the second refused naming the first, the first ends well?
. "$(dirname "$0")/../lib.sh"
study; pulseStudy -case . > log.1 2>&1 & p=$!; sleep 4; try second pulseStudy -case .; wait $p; echo "first rc=$?"; tail -2 log.1 | cut -c1-200
