#!/bin/bash
# a35 (class 1/2 in the tutorials' Allrun scripts without options): the indentation tutorial (smoke protocol) run by its ./Allrun; then the user changes constant/indenterProperties' radius 22.5 -> 20 um and runs ./Allrun again: the steps refused/skipped SAYING that the results are those of the earlier inputs (and how to run again), or exit 0 with the old results as if new?
. "$(dirname "$0")/../lib.sh"
indAllrun; run 250 ./Allrun > ../log.a1 2>&1; echo "   first Allrun: $(ls log.* | tr '\n' ' ')"; md5sum postProcessing/indentation/force.dat > ../m
sed -i 's/^\( *radius *\)22.5e-6;/\120e-6;/' constant/indenterProperties; grep -a '^ *radius' constant/indenterProperties | tr -s ' '
run 250 ./Allrun > ../log.a2 2>&1; echo "   second Allrun: $(cat ../log.a2 | grep -a -v '^ *$' | head -6 | cut -c1-200 | tr '\n' '|')"; echo "   force.dat $(md5sum -c ../m 2>&1 | awk '{print $2}')"
