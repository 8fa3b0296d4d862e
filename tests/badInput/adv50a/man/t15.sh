. /work/wt/adv50a/tests/badInput/adv50a/lib.sh > /dev/null 2>&1
rz() { mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize 0.1e-6; }
rz; mset maxElements 98; cm "" 60 | cut -c1-250
mdir quarter3D; mset maxElements 2680; cm "" 60 | cut -c1-250
mdir quarter3D; mset maxElements 2682; cm "" 60 | cut -c1-250
N=$(grep -a -o 'would have [0-9]*' $W/try.log | grep -o '[0-9]*'); echo "N=$N"; for m in $((N-1)) $N; do mdir quarter3D; mset maxElements $m; cm "" 200 | cut -c1-200; grep -a -o 'hexahedra [0-9]*' $W/try.log | head -1; done
rm -rf $W
