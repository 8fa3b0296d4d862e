#!/bin/bash
# i02 (class 6, structured r-z sizes): meshType structured in r-z with sizes whose counts are coupled across blocks (the user
# guide: "some elements are smaller than requested"): (a) nucleusSize 2e-6, cytoplasmSize 2e-6, membraneSize 5e-9 (a fine
# membrane drives the blocks around it); (b) membraneSize 0.4e-6 but membraneLayers 20 with membraneThickness 1e-6; (c) all
# sizes 2e-9 (far above maxElements). Each either meshes within memory (maxRSS below 1 GB, under 300 s) or is refused
# before meshing naming maxElements and the count; never allocation until killed, never a count far above maxElements meshed.
. "$(dirname "$0")/../lib.sh"
mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize 5e-9; cm; grep -a -i -m3 'element\|nodes' $W/try.log | cut -c1-200
mdir; mset meshType structured; mset membraneLayers 20; mset membraneThickness 1e-6; cm; grep -a -i -m3 'element\|nodes' $W/try.log | cut -c1-200
mdir; mset meshType structured; mset nucleusSize 2e-9; mset cytoplasmSize 2e-9; mset membraneSize 2e-9; cm; grep -a -i -m3 'element\|nodes' $W/try.log | cut -c1-200
