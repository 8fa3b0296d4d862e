#!/bin/bash
# x49: sweepCase where <case>.sweep_<name>_base is a USER's folder (same name by chance, holding a file): refused before anything, the user's folder and file kept?
. "$(dirname "$0")/../lib.sh"
ind; mkdir ../ind.sweep_k_base; echo mine > ../ind.sweep_k_base/notes.txt
run 200 sweepCase -case . -entry constant/indenterProperties/radius -values "22e-6" -run cellIndentationFoam -name k -nProcs 1 -output "F=postProcessing/indentation/peaks.dat:-1:force" > ../log.s 2>&1; tail -3 ../log.s | cut -c1-300; cat ../ind.sweep_k_base/notes.txt; ls ../ind.sweep_k_base
