#!/bin/bash
# w96: sweepCase -run ./Allrun on a user's finished blast preview copy (results in it): the user's case untouched, the table written?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/c; cd $W/c; o="-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 2e-9 -writeInterval 1e-9 -noPlots -noVTK"; ./Allrun $o > log.prep 2>&1; echo "user's run rc=$?"; snap ../before
run 280 sweepCase -case . -entry constant/fsiProperties/interface/mapTolerance -values "0.1 0.2" -run "./Allrun $o" -output "p=postProcessing/solidProbes/0/solidProbes.dat:-1:1" > log.sw 2>&1; echo "sweep rc=$?"; tail -5 log.sw | cut -c1-200
echo "user's case, gone: $(gone ../before | tr '\n' ' ')"; ls .. | tr '\n' ' '
