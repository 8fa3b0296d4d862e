#!/bin/bash
# b47 (class 1, a blast restart with the material set changed through the environment): the case's solidProperties #includes "$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4"; after a run to 2 ns, the restart to 3 ns with PROJECT_DIR pointing to a copy of etc/ whose membrane C10 is x10: refused naming constant/solidProperties (its expanded contents differ), nothing changed; with PROJECT_DIR pointing to an identical copy: continues?
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/projA $W/projB; cp -r "$ROOT/etc" $W/projA/; cp -r "$ROOT/etc" $W/projB/; sed -i 's/^\( *C10 *\)166.67;/\11666.7;/' $W/projA/etc/caseDicts/cellMaterials/textFactor4; grep -a -c '1666.7' $W/projA/etc/caseDicts/cellMaterials/textFactor4 | sed 's/^/   edited lines: /'
blastDone; latest; blastEnd 3e-9 1e-9; sums > ../before
PROJECT_DIR=$W/projA tryf "PROJECT_DIR -> a set with membrane C10 x10" cellBlastFoam; nochange ../before
PROJECT_DIR=$W/projB tryf "PROJECT_DIR -> an identical copy" cellBlastFoam; echo "   times: $(ls -d [1-9]* | tr '\n' ' ')"
