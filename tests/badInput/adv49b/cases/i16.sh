#!/bin/bash
# i16 (class 4, solidSubcycles at and beyond its range [1, 1000], whole): in a blast copy run for 2e-11 s: 0, -1, 2.5, 1e9,
# 1001, 4294967297 (2^32 + 1: 1 if cut to 32 bits), 2147483649, "4 4", 0x4, and the accepted edges 1000, 1e3, 1: each
# refused naming constant/fsiProperties, coupling/solidSubcycles, the value and the range, exit non-zero, nothing written; the
# accepted ones run (exit 0). Never 4294967297 run as 1.
. "$(dirname "$0")/../lib.sh"
blast; short; cp constant/fsiProperties ../f0
for v in 0 -1 2.5 1e9 1001 4294967297 2147483649 "4 4" 0x4 1000 1e3 1; do cp ../f0 constant/fsiProperties; fsiSet solidSubcycles "$v" > /dev/null
  tryt 200 "solidSubcycles $v" cellBlastFoam; echo "   ran: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')| $(grep -a -i -m1 'subcycl' $W/try.log | cut -c1-160)"; rm -rf [1-9]* solid postProcessing; done
