#!/bin/bash
# i51: cellMesh -dict pointing at a missing file
. "$(dirname "$0")/../lib.sh"
ind; cellMesh -dict system/noSuchDict > log.cm 2>&1; rc=$?; grep -A3 "FATAL" log.cm | head -4; echo "rc=$rc"
