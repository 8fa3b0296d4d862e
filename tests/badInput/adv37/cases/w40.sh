#!/bin/bash
# w40: ind finished: postProcessing/indentation/force.dat replaced by a symlink to a user's file elsewhere, re-run with -overwrite: is the user's file written through the link?
. "$(dirname "$0")/../lib.sh"
indDone; cp postProcessing/indentation/force.dat ../userForce.dat; md5sum ../userForce.dat > ../u.md5; rm postProcessing/indentation/force.dat; ln -s ../../../userForce.dat postProcessing/indentation/force.dat; ls -la postProcessing/indentation/force.dat
run 120 cellIndentationFoam -overwrite > log.r 2>&1; fatal log.r 4; tail -1 log.r; md5sum -c ../u.md5 && echo "user's file unchanged"; ls -la postProcessing/indentation | tail -7
