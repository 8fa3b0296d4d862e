#!/bin/bash
# a13 (class 4+2, sweepCase -entry leaving its copy through '..'): the smoke indentation case $W/ind; sweepCase -case . -entry ../ind/constant/indenterProperties/radius -values "20e-6 25e-6" -run cellIndentationFoam: refused (an entry outside the case), or each run edits the ORIGINAL case's indenterProperties (the copy's ../ind is the case itself) while the copies run unchanged, the table listing two radii with one result?
. "$(dirname "$0")/../lib.sh"
ind; md5sum constant/indenterProperties > ../m; grep -a '^ *radius' constant/indenterProperties | tr -s ' '
tryf "sweep radius via ../ind" sweepCase -case . -entry ../ind/constant/indenterProperties/radius -values "20e-6 25e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:1"; grep -a '^|' $W/try.log | head -4
echo "   the case's indenterProperties: $(md5sum -c ../m 2>&1 | awk '{print $2}') radius now: $(grep -a '^ *radius' constant/indenterProperties | tr -s ' ')"; echo "   left: $(ls -d $W/ind.* 2>/dev/null | tr '\n' ' ') report: $(ls postProcessing/sweep 2>/dev/null | tr '\n' ' ')"
