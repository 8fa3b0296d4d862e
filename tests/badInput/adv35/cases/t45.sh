#!/bin/bash
# t45: solidToFoam after a new run (-overwrite, fewer rows) over an earlier conversion: time directories of the old results must not stay in the region
. "$(dirname "$0")/../lib.sh"
indDone; solidToFoam postProcessing/indentation/solid.h5 > log.s1 2>&1; echo "first conversion: $(ls -d [0-9]* | tr '\n' ' ')"
python3 - <<'P'
import re; f='constant/indenterProperties'; s=open(f).read(); s=re.sub(r"\(C1  unload.*?\)\n", "", s); open(f,'w').write(s)
P
cellIndentationFoam -overwrite > log.2 2>&1; echo "second run rc=$?"; h5ls postProcessing/indentation/solid.h5/steps | wc -l
solidToFoam postProcessing/indentation/solid.h5 > log.s2 2>&1; echo "second conversion rc=$? ($(tail -2 log.s2 | head -1))"; echo "time directories now: $(ls -d [0-9]* | tr '\n' ' ')"
for t in $(ls -d [0-9]*); do echo "$t: $(stat -c %y $t/solid/D | cut -c12-19)"; done
