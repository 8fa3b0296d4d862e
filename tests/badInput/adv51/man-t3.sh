#!/bin/bash
# man-t3.sh (adv51, by hand, phase 2): n02 (a) and (b) on the merge: the rebuilt short preview (sb of /tmp/adv51b-) with a
# fifth water probe outside the mesh, then every probe outside (probeLocations edited on its one line)
cd /work/wt/adv51/tests/badInput; export ADV=/tmp/adv51b-adv51; . adv51/lib.sh
sb; cp -a . ../b0
for new in "(9.9999999999999995e-08 1.0000000000000001e-05 0) (1e-3 1e-3 0)" "(1e-3 1e-3 0) (-1 -1 0)"; do
  cd $W; rm -rf blast; cp -a b0 blast; cd blast
  sed -i "s/probeLocations ( (9.9999999999999995e-08 1.0000000000000001e-05 0) );/probeLocations ( $new );/" system/controlDict
  grep -o "probeLocations ([^;]*;" system/controlDict
  tryt 120 "probes $new" cellBlastFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | times: $(ls -d [0-9]* | tr '\n' ' ')"; done
