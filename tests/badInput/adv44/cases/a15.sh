#!/bin/bash
# a15 (class 4, sweepCase over an entry that the case's own options file overrides): the smoke indentation with constant/indenterProperties ending in #sinclude "indenterProperties.allrun" (the tutorials' pattern for Allrun options), that file holding "radius 22.5e-6;"; sweepCase -entry constant/indenterProperties/radius -values "20e-6 25e-6": refused or warned (the value is overridden), or two runs of one radius tabulated as two radii?
. "$(dirname "$0")/../lib.sh"
ind; echo '#sinclude "indenterProperties.allrun"' >> constant/indenterProperties; echo 'radius 22.5e-6;' > constant/indenterProperties.allrun; grep -a '^ *radius' constant/indenterProperties | tr -s ' '
tryf "sweep radius" sweepCase -case . -entry constant/indenterProperties/radius -values "20e-6 25e-6" -run "cellIndentationFoam > log.run 2>&1" -output "F=postProcessing/indentation/peaks.dat:-1:1" -output "R=log.run:/Indenter: radius (\S+) m/"; grep -a '^|\|note\|warn' $W/try.log | head -5
