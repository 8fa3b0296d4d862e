#!/bin/bash
# o01: ind: cellIndentationFoam re-run over a finished case without -overwrite
. "$(dirname "$0")/../lib.sh"
indDone; sums > ../before; cellIndentationFoam 2>&1 | tail -5; echo "rc=${PIPESTATUS[0]}"; sums > ../after; cmp -s ../before ../after && echo "files unchanged" || echo "FILES CHANGED"
