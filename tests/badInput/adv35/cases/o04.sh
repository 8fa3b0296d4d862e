#!/bin/bash
# o04: blast: cellBlastFoam re-run over a finished case without -overwrite
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../before; cellBlastFoam 2>&1 | tail -5; echo "rc=${PIPESTATUS[0]}"; sums > ../after; cmp -s ../before ../after && echo "files unchanged" || echo "FILES CHANGED"
