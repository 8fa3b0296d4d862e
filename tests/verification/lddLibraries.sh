#!/bin/bash
# Every library and application we build resolves all its symbols against
# the installed OpenFOAM (catches a label-size or ABI mismatch, which links
# silently for shared libraries).
set -euo pipefail
. "$(dirname "$0")/../../etc/bashrc"
status=0
n=0
for f in "$FOAM_USER_LIBBIN"/*.so "$FOAM_USER_APPBIN"/*
do
    # Only ELF files: FOAM_USER_APPBIN also holds the Python utilities'
    # wrapper scripts (calibrateCell, sweepCase)
    [ "$(head -c 4 "$f" | tr -d '\0')" = $'\x7fELF' ] || continue
    n=$((n + 1))
    out=$(ldd -r "$f" 2>&1)
    if grep -qE "undefined symbol|not found" <<< "$out"
    then
        echo "$f:"; echo "$out" | grep -E "undefined symbol|not found" | head
        status=1
    fi
done
echo "lddLibraries: checked $n files"
[ "$n" -gt 3 ] || { echo "lddLibraries: nothing built?"; exit 1; }
exit $status
