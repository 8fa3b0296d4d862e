#!/bin/bash
# w61: pulseStudy: the same overpressure spelled twice (30e6 3e7), nProcs 1.5, nProcs 0, an empty duration ()
. "$(dirname "$0")/../lib.sh"
study; cp system/pulseStudyDict ../orig; for e in "overpressure (30e6 3e7)" "nProcs 1.5" "nProcs 0" "duration ()"; do cp ../orig system/pulseStudyDict; setStudy "${e%% *}" "${e#* }"; try "$e" pulseStudy -case .; done
