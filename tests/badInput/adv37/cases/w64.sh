#!/bin/bash
# w64: pulseStudy: baseCase given through a symlinked path (a link to the tutorials folder) and a baseCase that does not exist
. "$(dirname "$0")/../lib.sh"
study; ln -s "$ROOT/tutorials/blast" ../linkedBlast; cp system/pulseStudyDict ../orig; sed -i "s|^baseCase .*|baseCase \"$W/linkedBlast/axisymmetricPreview\";|" system/pulseStudyDict; run 240 pulseStudy -case . > log.1 2>&1; fatal log.1 3; tail -2 log.1 | cut -c1-200
cp ../orig system/pulseStudyDict; sed -i "s|^baseCase .*|baseCase \"$W/nothere\";|" system/pulseStudyDict; try missing pulseStudy -case .; git -C "$ROOT" status --short tutorials | head -3
