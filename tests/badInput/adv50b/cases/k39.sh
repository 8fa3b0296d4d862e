#!/bin/bash
# k39 (class 4, motionDistance in the wrong dictionary and given twice): short preview: (a) motionDistance in coupling{} (not interface{}); (b) motionDistance twice in interface{}; (c) motionDistance both in fsiProperties and in fsiProperties.allrun with other values (the .allrun replaces by design: the value used is said?); (d) motionDistance removed (the guide: optional, own motion or dynamicMeshDict's solver). Expected: (a) unknown keyword in coupling with the closest valid one (or where it belongs); (b) given twice naming both; (c) runs with the .allrun's value; (d) runs with the dynamicMeshDict motion or refused naming what is missing.
. "$(dirname "$0")/../lib.sh"
sb; F=constant/fsiProperties; cp $F $W/f0
sed -i '/^ *motionDistance /d' $F; fsiSet motionDistance 5e-6 > /dev/null; grep -n motionDistance $F | head -3; tryt 150 "(a) motionDistance in coupling{}" cellBlastFoam; rm -rf [1-9]* solid postProcessing; cp $W/f0 $F
dupe $F motionDistance; tryt 150 "(b) motionDistance twice" cellBlastFoam; rm -rf [1-9]* solid postProcessing; cp $W/f0 $F
echo 'interface { motionDistance 3e-6; }' > constant/fsiProperties.allrun; tryt 150 "(c) 5e-6 here, 3e-6 in .allrun" cellBlastFoam; grep -a -i -m2 'motion' $W/try.log | cut -c1-200 | sed 's/^/   log: /'; rm -rf [1-9]* solid postProcessing constant/fsiProperties.allrun
sed -i '/^ *motionDistance /d; /^ *motionNearest /d' $F; tryt 150 "(d) no motionDistance/motionNearest" cellBlastFoam; grep -a -i -m2 'motion' $W/try.log | cut -c1-200 | sed 's/^/   log: /'; cp $W/f0 $F
