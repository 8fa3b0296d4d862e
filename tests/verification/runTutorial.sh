#!/bin/bash
# Smoke run of a tutorial: its Allrun in a scratch copy (the tutorial itself
# is untouched); fails if any step fails or a log reports a FOAM error.
set -euo pipefail
src=$(cd "$1" && pwd)
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rel=${src#"$root"/}
mkdir -p "$work/$(dirname "$rel")"
cp -r "$src" "$work/$rel"
# Shared scripts one level up (plot scripts) and the environment
cp "$(dirname "$src")"/plot* "$work/$(dirname "$rel")"/ 2>/dev/null || true
ln -s "$root/etc" "$work/etc"
ln -s "$root/platforms" "$work/platforms"
cd "$work/$rel"
./Allclean > /dev/null 2>&1 || true
./Allrun
if grep -l "FOAM FATAL" log.* 2>/dev/null; then
    echo "runTutorial: FOAM error in the logs above"; exit 1
fi
ls *.png > /dev/null
echo "runTutorial: $rel passed"
