#!/bin/bash
# i04 (class 4/6, structured r-z at the edges of its ranges): meshType structured with membraneThickness just below its upper
# bound min(H^2/a, a^2/H) (the user guide's range; H 7.9e-6, a 8.4e-6: 7.4298e-6) and at 99.9 % of it; nucleusVolumeFraction
# 1e-6 and 0.999; membraneLayers 1 and 20 with the default thickness. Each meshes with no inverted element (the quality
# table's minimum Jacobian > 0) or is refused naming the entry and its range (or what does not fit); no crash, no hang.
. "$(dirname "$0")/../lib.sh"
for e in "membraneThickness 7.4298e-6" "membraneThickness 7.42e-6" "nucleusVolumeFraction 1e-6" "nucleusVolumeFraction 0.999" "membraneLayers 1" "membraneLayers 20"; do
  mdir; mset meshType structured; mset $e; cm; echo "   [$e] $(grep -a -A5 'Mesh quality' $W/try.log | cut -c1-150 | tr -s ' ' | tr '\n' '|')"; done
