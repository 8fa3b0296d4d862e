#!/bin/bash
# i52: ind Allrun with an option (it takes none)
. "$(dirname "$0")/../lib.sh"
ind; cp "$ROOT/tutorials/indentation/averageCell"/All* .; ./Allrun -foo 2>&1 | tail -2; echo "rc=${PIPESTATUS[0]}"; ls
