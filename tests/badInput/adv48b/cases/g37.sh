#!/bin/bash
# g37 (class 4, the Fig. 10 probe's dictionary at its edges and near-miss words) the prepared preview, endTime 2e-11, constant/solidProperties interfaceProbe: heightFraction 0, 1, 1.0000000000000002, -0, 4.9e-324, nan; regions (nucleus nucleus), (cytoplasm nucleous); side Outer, inner: each refused before the run naming the entry, the value (digits that show it outside) and the valid range or words with the closest, or accepted if in range (then the probe's location printed).
. "$(dirname "$0")/../lib.sh"
blast; short
each constant/solidProperties "heightFraction 0" "heightFraction 1" "heightFraction 1.0000000000000002" "heightFraction -0" "heightFraction 4.9e-324" "heightFraction nan" "regions (nucleus nucleus)" "regions (cytoplasm nucleous)" "side Outer" "side inner" -- cellBlastFoam
