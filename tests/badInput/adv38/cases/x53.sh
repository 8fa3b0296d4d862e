#!/bin/bash
# x53: planeWave on a finished blast whose latest time's record uniform/inputDigests was removed (the user cleaned uniform/), and on one whose 0/T ".*" pattern was changed to fixedValue 320 after the run: refused / said / silent?
. "$(dirname "$0")/../lib.sh"
blastDone; cp -r . ../keep; rm -f 2e-09/uniform/inputDigests; try "record removed" planeWave -Z 20e-6 -dz 50e-9
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; sed -i 's/^\(\s*\)".\*".*/\1".*" { type fixedValue; value uniform 320; }/' 0/T; try "0/T pattern changed" planeWave -Z 20e-6 -dz 50e-9
