#!/bin/bash
# f09 (class 1/2, indentation, solid.xmf removed from a killed run), restart: continues with solid.xmf written again listing every step of solid.h5, or refuses naming solid.xmf; never an xmf that lists fewer steps than solid.h5 at the end.
. "$(dirname "$0")/../lib.sh"
ik; rm -f postProcessing/indentation/solid.xmf
tryt 240 "solid.xmf removed" cellIndentationFoam; cont; after; echo "   xmf steps $(xmfsteps postProcessing/indentation/solid.xmf), h5 steps $(h5steps postProcessing/indentation/solid.h5)"
