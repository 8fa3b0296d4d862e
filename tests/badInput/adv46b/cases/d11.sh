#!/bin/bash
# d11 (class 1, indentation restart after one indenterProperties entry changed at a time: penaltyFactor 10->12, holdGrowth 1.5->1.6, maxDeltaT 5->4, tolerance 1e-9->5e-10, forceTarget 0.02e-9->0.03e-9, holdDeltaT0 0.01->0.02): each refused naming the entry, or (for an entry that cannot change the result) accepted.
. "$(dirname "$0")/../lib.sh"
for e in "penaltyFactor 12" "holdGrowth 1.6" "maxDeltaT 4" "tolerance 5e-10" "forceTarget 0.03e-9" "holdDeltaT0 0.02"; do cd $W; rm -rf ind; ik; sete constant/indenterProperties $e || continue
  tryt 200 "$e" cellIndentationFoam; cont; after; done
