#!/bin/bash
# i36 (class 4/SILENT, labels beyond 32 bits in fsiProperties): a blast copy run for 2e-11 s with coupling{} maxIter
# 4294967326 (30 if cut to 32 bits), reuse 4294967296 (0), interface{} motionNearest 4294967304 (8), coupling{} maxIter
# -4294967266 (30 cut), solidSubcycles 8589934593 (1 cut): each refused naming the entry, the digits given and the largest
# 32-bit label; never run as the cut value (exit 0).
. "$(dirname "$0")/../lib.sh"
blast; short; cp constant/fsiProperties ../f0
for e in "maxIter 4294967326" "reuse 4294967296" "motionNearest 4294967304" "maxIter -4294967266" "solidSubcycles 8589934593"; do cp ../f0 constant/fsiProperties; fsiSet $e > /dev/null
  tryt 120 "[$e]" cellBlastFoam; echo "   ran: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"; rm -rf [1-9]* solid postProcessing; done
