#!/bin/bash
# x00: base cases built (ind, blast) and timed: blastDone and indDone
. "$(dirname "$0")/../lib.sh"
s=$(date +%s.%N); blastDone; echo "blastDone $(echo "$(date +%s.%N)-$s"|bc) s: $(ls -d [0-9]*|tr '\n' ' ')"; ls postProcessing
s=$(date +%s.%N); indDone; echo "indDone $(echo "$(date +%s.%N)-$s"|bc) s"; ls postProcessing/indentation
