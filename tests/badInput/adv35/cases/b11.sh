#!/bin/bash
# b11: blast: equationOfState unknown
. "$(dirname "$0")/../lib.sh"
blast; setd constant/thermophysicalProperties equationOfState mieGrunaisen
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
