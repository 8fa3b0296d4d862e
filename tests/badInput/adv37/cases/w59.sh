#!/bin/bash
# w59: pulseStudy grid values at the edges: overpressure (nan), (inf), (-30e6), (0); duration (0), (-2e-9), (nan); refused before anything runs, naming the entry?
. "$(dirname "$0")/../lib.sh"
study; cp system/pulseStudyDict ../orig; for e in "overpressure (nan)" "overpressure (inf)" "overpressure (-30e6)" "overpressure (0)" "duration (0)" "duration (-2e-9)" "duration (nan)"; do cp ../orig system/pulseStudyDict; setStudy "${e%% *}" "${e#* }"; try "$e" pulseStudy -case .; done; ls postProcessing 2>/dev/null
