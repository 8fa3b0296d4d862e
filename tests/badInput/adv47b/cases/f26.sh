#!/bin/bash
# f26 (class 4, a correlation at its bound and one ulp beyond): pulseStudy -dict pulseStudyDict.uncertainty with maxPoints 1: correlation -0.60 -> 1.0000000000000002 refused naming correlation and [-1, 1]; -> 1 (the bound, positive semi-definite) accepted by the correlation check (the refusal names maxPoints only); -> -1.0000000000000002 refused.
. "$(dirname "$0")/../lib.sh"
study; cp $ROOT/tutorials/blast/pulseStudy/system/pulseStudyDict.uncertainty system/; echo "maxPoints 1;" >> system/pulseStudyDict.uncertainty; cp system/pulseStudyDict.uncertainty ../u0
for c in 1.0000000000000002 1 -1.0000000000000002; do cp ../u0 system/pulseStudyDict.uncertainty; sed -i "s/nucleus.C10 -0.60/nucleus.C10 $c/" system/pulseStudyDict.uncertainty; n=$(grep -c "nucleus.C10 $c))" system/pulseStudyDict.uncertainty)
  tryt 60 "correlation $c (edit $n)" pulseStudy -dict system/pulseStudyDict.uncertainty; done
