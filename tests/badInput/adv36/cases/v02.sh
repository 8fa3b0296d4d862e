#!/bin/bash
# v02: blast: -overwrite with a good input, SIGTERM at 1.5 s (before its first write): results put back or kept aside?
. "$(dirname "$0")/../lib.sh"
blastDone; contents > ../before; blastEnd 2e-8 1e-8
cellBlastFoam -overwrite > log.ow 2>&1 & p=$!; sleep 1.5; kill -TERM $p; wait $p; echo "rc=$?"; tail -3 log.ow
echo "lost:"; lost ../before | wc -l; ls -a . solid postProcessing/* | tr '\n' ' '; echo
