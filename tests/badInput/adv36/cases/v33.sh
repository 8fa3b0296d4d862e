#!/bin/bash
# v33: ind: solidToFoam -region solid twice (identical re-conversion) then -region cellB, then solid again: each run's set of times as expected, exit 0
. "$(dirname "$0")/../lib.sh"
indDone; for r in solid solid cellB solid; do solidToFoam postProcessing/indentation/solid.h5 -region $r > log.s 2>&1; echo "-region $r rc=$? $(grep -a '^Wrote' log.s)"; done; ls 2.1 | tr '\n' ' '
