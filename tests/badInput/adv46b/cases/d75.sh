#!/bin/bash
# d75 (class 2, cellIndentationFoam -overwrite over a finished run whose postProcessing/indentation also holds a user's notes.txt and force.dat.bak): the user files kept (or the start refused naming them); never removed with the run's results.
. "$(dirname "$0")/../lib.sh"
idn; echo precious > postProcessing/indentation/notes.txt; cp postProcessing/indentation/force.dat postProcessing/indentation/force.dat.bak; md5sum postProcessing/indentation/force.dat.bak > ../m
tryt 200 "-overwrite with user files in the folder" cellIndentationFoam -overwrite; echo "   notes.txt: $(cat postProcessing/indentation/notes.txt 2>&1); force.dat.bak: $(md5sum -c ../m 2>&1 | awk "{print \$2}")"; ls -a postProcessing/indentation | tr "\n" " "
