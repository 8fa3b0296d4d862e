. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
for kv in "cellDiameter 1e200" "cellHeight 1e200" "cellDiameter 1e-200" "membraneThickness 1e-200" "nucleusVolumeFraction 1e-200" "contactRadius 1e200" "contactDepth 1e-200" "nucleusSize 1e200"; do mdir; set -- $kv; mset $1 $2; echo "r-z $kv: $( (ulimit -v 3000000; cm "" 60) | cut -c1-230)"; done
for kv in "cellDiameter 1e200" "membraneThickness 1e-200" "cellHeight 1e-200"; do mdir quarter3D; set -- $kv; mset $1 $2; echo "q3 $kv: $( (ulimit -v 3000000; cm "" 60) | cut -c1-230)"; done
rm -rf $W
