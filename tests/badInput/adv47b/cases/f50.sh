#!/bin/bash
# f50 (class 4, cellIndentationFoam's penetration tolerance at its bound): maxDepthIncrement 0.1e-6, tolerance 1e-8 (exactly a tenth: accepted, the smoke runs) and 1.0000000000000002e-8 (one ulp above: refused naming tolerance, maxDepthIncrement and the bound).
. "$(dirname "$0")/../lib.sh"
ind; cp constant/indenterProperties ../ip0; /usr/bin/python3 -c "print('   0.1e-6/10 == 1e-8:', 0.1e-6/10 == 1e-8)"
for v in 1e-8 1.0000000000000002e-8; do cp ../ip0 constant/indenterProperties; sete constant/indenterProperties tolerance $v; tryt 200 "tolerance $v" cellIndentationFoam; after; rm -rf postProcessing; done
