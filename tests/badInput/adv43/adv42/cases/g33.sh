#!/bin/bash
# g33 (class 4, the function object's entries in controlDict): fresh blast (endTime 1e-9); fluidProbes' first probe location (x) and its writeInterval set to nan, inf, -1, 1e400; a probe location given twice; `fields (p p)`: refused naming controlDict, the function object and the entry?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 1e-9 1e-9; cp system/controlDict $W/cd.orig
for v in nan inf -1 1e400; do cp $W/cd.orig system/controlDict; sed -i "s/(1e-7 90e-6 0)/($v 90e-6 0)/" system/controlDict; tryf "probe x $v" cellBlastFoam; rm -rf [1-9]* solid postProcessing
  cp $W/cd.orig system/controlDict; sed -i "0,/writeInterval   1;/s//writeInterval   $v;/" system/controlDict; grep -q "writeInterval   $v;" system/controlDict || echo "   (edit not applied)"; tryf "fluidProbes writeInterval $v" cellBlastFoam; rm -rf [1-9]* solid postProcessing; done
cp $W/cd.orig system/controlDict; sed -i "s/(1e-7 90e-6 0)/(1e-7 90e-6 0) (1e-7 90e-6 0)/" system/controlDict; tryf "a probe location twice" cellBlastFoam; echo "   fluidProbes/0/p header: $(grep -a -m6 '^#' postProcessing/fluidProbes/0/p 2>/dev/null | tr '\n' ' ' | cut -c1-200)"; rm -rf [1-9]* solid postProcessing
cp $W/cd.orig system/controlDict; sed -i "s/fields          (p);/fields          (p p);/" system/controlDict; tryf "fields (p p)" cellBlastFoam; rm -rf [1-9]* solid postProcessing; cp $W/cd.orig system/controlDict
