#!/bin/bash
# i19: ind: material C10 negative (region override)
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's#cellMaterials/textFactor4"#&\n    cytoplasm { C10 -1; }#' constant/solidProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
