#!/bin/bash
# w35: ind killed at 2 s, the bead radius changed 22.5 -> 20 um, restart: refused naming radius?
. "$(dirname "$0")/../lib.sh"
indKilled 2; setd constant/indenterProperties radius 20e-6; run 120 cellIndentationFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
