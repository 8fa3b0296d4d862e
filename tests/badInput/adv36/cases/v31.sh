#!/bin/bash
# v31: ind: solidToFoam -region U, -region uniform, -region a/b, -region polyMesh, -region '', -region constant
. "$(dirname "$0")/../lib.sh"
indDone; for r in U uniform a/b polyMesh "" constant; do solidToFoam postProcessing/indentation/solid.h5 -region "$r" > log.s 2>&1; echo "-region '$r' rc=$?"; grep -a -A2 "FATAL" log.s | sed -n 2,3p | cut -c1-250; grep -a "^Wrote" log.s; done
ls -a 2.1 2>/dev/null | tr '\n' ' '
