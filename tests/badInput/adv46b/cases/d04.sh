#!/bin/bash
# d04 (class 1, blast restart after a new constant/fsiProperties.allrun, the #sinclude of fsiProperties, that did not exist at the first run): coupling { scheme aitken; } in it: refused naming fsiProperties (coupling/scheme) or the added file; never "Continuing" with another scheme.
. "$(dirname "$0")/../lib.sh"
bd; rs; sums > ../s0; ls constant
printf "coupling { scheme aitken; }\n" > constant/fsiProperties.allrun
tryt 240 "new fsiProperties.allrun with scheme aitken" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
