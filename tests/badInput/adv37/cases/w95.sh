#!/bin/bash
# w95: pulseStudy whose baseCase is a user's own FINISHED preview case (results in it): are the user's results in the base case kept?
. "$(dirname "$0")/../lib.sh"
blastDone; snap ../before; cd ..; mv blast userCase; study; sed -i "s|^baseCase .*|baseCase \"$W/userCase\";|; s/^baseOptions .*/baseOptions ();/" system/pulseStudyDict
run 240 pulseStudy -case . > log.1 2>&1; fatal log.1 4; tail -2 log.1 | cut -c1-200; cd $W/userCase; echo "user's case, gone: $(gone ../before | tr '\n' ' ')"; ls | tr '\n' ' '
