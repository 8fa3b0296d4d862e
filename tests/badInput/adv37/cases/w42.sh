#!/bin/bash
# w42: solidToFoam on a solid.h5 cut to half its size (a copied file that did not finish): refused naming the file, nothing written?
. "$(dirname "$0")/../lib.sh"
blastDone; cp solid/solid.h5 ../cut.h5; truncate -s $(( $(stat -c %s ../cut.h5) / 2 )) ../cut.h5; cp ../cut.h5 solid/cut.h5
try cut solidToFoam solid/cut.h5; ls -d */solid 2>/dev/null | tr '\n' ' '; ls constant | tr '\n' ' '
