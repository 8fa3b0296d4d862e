#!/bin/bash
# f22 (class 4, subnormal and tiny numbers in a grid): pulseStudy overpressure (4.9e-324), then (1e-300), then duration (1e-17): each refused before anything runs naming the entry and why (below OpenFOAM's reader, or below what the Allrun's pulse can be); never a point prepared and run.
. "$(dirname "$0")/../lib.sh"
for e in "overpressure (4.9e-324)" "overpressure (1e-300)" "duration (1e-17)"; do cd $W; rm -rf study; study; setStudy $e
  tryt 90 "$e" pulseStudy; echo "   points: $(ls postProcessing/pulseStudy/points 2>/dev/null | tr '\n' ' ')"; done
