#!/bin/bash
# w93: ind killed after a checkpoint: one bit flipped in the middle of restart.h5, restart: refused naming the file?
. "$(dirname "$0")/../lib.sh"
indKilled 0.5; f=postProcessing/indentation/restart.h5; n=$(stat -c %s $f); off=$((n/2)); /usr/bin/python3 -c "
f=open('$f','r+b'); f.seek($off); b=f.read(1); f.seek($off); f.write(bytes([b[0]^0x01])); f.close()"
run 200 cellIndentationFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
