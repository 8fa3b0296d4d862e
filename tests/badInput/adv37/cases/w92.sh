#!/bin/bash
# w92: blast: one bit flipped in the middle of solid/solid.h5 (last step's data), then solidToFoam and a restart: the damage detected?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; f=solid/solid.h5; n=$(stat -c %s $f); off=$((n*3/4)); /usr/bin/python3 -c "
import sys; f=open('$f','r+b'); f.seek($off); b=f.read(1); f.seek($off); f.write(bytes([b[0]^0x10])); f.close()"
h5dump -H $f > /dev/null 2>&1 && echo "h5dump -H reads it"; try solidToFoam solidToFoam $f; run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
