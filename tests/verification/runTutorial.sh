#!/bin/bash
# Smoke run of a tutorial: its Allrun in a scratch copy outside the tree
# (the tutorial itself is untouched); fails if any step fails or a log
# reports a FOAM error.
set -euo pipefail
src=$(cd "$1" && pwd)
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rel=${src#"$root"/}
# A copy anywhere runs in the project's environment (its shared scripts
# from $FOAM_TUTORIALS)
cp -r "$src" "$work/"
cd "$work/$(basename "$src")"
./Allclean > /dev/null 2>&1 || true
./Allrun
if grep -l "FOAM FATAL" log.* 2>/dev/null; then
    echo "runTutorial: FOAM error in the logs above"; exit 1
fi
ls *.png > /dev/null
echo "runTutorial: $rel passed"
