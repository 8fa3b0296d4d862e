#!/bin/bash
# q04: rhoRiemannFoam (waterPulseWall, probes) other ways into post-processing: -postProcess -func probes, -postProcess -latestTime; then OpenFOAM's postProcess utility; the probe log kept? a restart to 6e-8 continues?
. "$(dirname "$0")/../lib.sh"
wpDone; sums > ../before
tryf "-postProcess -func probes" rhoRiemannFoam -postProcess -func probes; nochange ../before
tryf "-postProcess -latestTime" rhoRiemannFoam -postProcess -latestTime; nochange ../before
sums > ../before2; tryf "postProcess (utility)" postProcess; echo "   by the utility alone:"; nochange ../before2
sed -i 's/^endTime .*/endTime 6e-8;/' system/controlDict; sed -i 's/^startFrom .*/startFrom latestTime;/' system/controlDict
tryf "restart to 6e-8" rhoRiemannFoam; echo "   times: $(ls -d [1-9]* | tr '\n' ' ')"
