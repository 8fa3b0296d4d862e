#!/bin/bash
# d54 (class 6, cellIndentationFoam fieldWriteInterval 1e-9 on the smoke table, 60 s): refused (writes more than a limit) or writes a bounded number of steps; disk growth reported; never filling the disk silently.
. "$(dirname "$0")/../lib.sh"
ind; sed -i "s/^fieldWriteInterval .*/fieldWriteInterval 1e-9;/" system/controlDict; grep fieldWriteInterval system/controlDict
tryt 60 "fieldWriteInterval 1e-9" cellIndentationFoam; echo "   output: $(du -sh postProcessing 2>/dev/null | cut -f1), solid.h5 steps $(h5steps postProcessing/indentation/solid.h5 2>/dev/null)"
