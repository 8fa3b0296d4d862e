#!/bin/bash
# w49: two planeWave at once on the same finished blast case: the second refused, or both write postProcessing/planeWave and the tables stay whole?
. "$(dirname "$0")/../lib.sh"
blastDone; planeWave -case . > log.pw1 2>&1 & p=$!; sleep 0.5; try second planeWave -case .; wait $p; echo "first rc=$?"; ls -la postProcessing/planeWave/0 2>/dev/null | tail -4; planeWave -case . > log.pw3 2>&1; echo "alone rc=$?"; for f in postProcessing/planeWave/0/*; do echo "$f $(md5sum < $f | cut -c1-8)"; done
