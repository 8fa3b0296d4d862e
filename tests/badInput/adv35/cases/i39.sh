#!/bin/bash
# i39: solidProperties: materials #include of a missing file
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's#cellMaterials/textFactor4#cellMaterials/nonexistent#' constant/solidProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
