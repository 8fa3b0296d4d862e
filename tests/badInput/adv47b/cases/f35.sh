#!/bin/bash
# f35 (environment, HOME unset or unusable): (a) the killed indentation restarted with HOME unset: runs to its end rc 0 (or a clear error); (b) solidToFoam with HOME=/proc/nonexistent; (c) pulseStudy with HOME unset on a dictionary with an error (nProcs 0): the same refusal as with HOME set, no traceback.
# (corrected after its first run: env cannot run the shell function tryt; HOME is unset in a subshell instead)
. "$(dirname "$0")/../lib.sh"
ik; ( unset HOME; tryt 200 "(a) cellIndentationFoam, HOME unset" cellIndentationFoam ); cont; after
HOME=/proc/nonexistent tryt 60 "(b) solidToFoam, HOME unusable" solidToFoam postProcessing/indentation/solid.h5; ls constant | tr '\n' ' '; echo
study; setStudy nProcs 0; ( unset HOME; tryt 60 "(c) pulseStudy nProcs 0, HOME unset" pulseStudy ); grep -a -c Traceback $W/try.log
