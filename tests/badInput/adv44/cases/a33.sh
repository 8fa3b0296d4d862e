#!/bin/bash
# a33 (class 4+2, a13's root with an ABSOLUTE entry path): two smoke indentation cases $W/ind and $W/other; in $W/ind: sweepCase -entry $W/other/constant/indenterProperties/radius -values "20e-6 25e-6" -run cellIndentationFoam: refused (a file outside the case), or the OTHER case's dictionary edited by each run and one result tabulated twice?
. "$(dirname "$0")/../lib.sh"
ind; cp -r $W/ind $W/other; md5sum $W/other/constant/indenterProperties > ../m
tryf "sweep an absolute entry path" sweepCase -case . -entry $W/other/constant/indenterProperties/radius -values "20e-6 25e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:1"; grep -a '^|' $W/try.log | head -4
echo "   the other case's indenterProperties: $(md5sum -c ../m 2>&1 | awk '{print $2}'), radius now: $(grep -a '^ *radius' $W/other/constant/indenterProperties | tr -s ' ')"
