#!/bin/bash
# v03: sod: rhoRiemannFoam re-run over finished results without -overwrite
. "$(dirname "$0")/../lib.sh"
sodDone; sums > ../before; rhoRiemannFoam > log.run 2>&1; echo "rc=$?"; grep -A2 FATAL log.run | head -3; sums > ../after; cmp -s ../before ../after && echo "files unchanged" || echo "FILES CHANGED"
