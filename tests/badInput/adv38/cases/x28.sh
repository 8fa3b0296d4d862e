#!/bin/bash
# x28: blast finished to 2 ns: the logs ROTATED/compressed (gzip of postProcessing/solidProbes/0/solidProbes.dat, the original gone; then gzip -k, both kept; then CRLF line ends by an editor) and a restart to 3 ns: refused naming the file with a way out / accepted where nothing changed?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; f=postProcessing/solidProbes/0/solidProbes.dat; cp -r . ../keep
gzip $f; try "gzip (original gone)" cellBlastFoam; gunzip $f.gz; gzip -k $f; try "gzip -k (both)" cellBlastFoam; rm -rf [3]e-09; ls postProcessing/solidProbes/0
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; sed -i 's/$/\r/' $f; try "CRLF" cellBlastFoam
