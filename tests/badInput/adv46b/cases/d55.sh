#!/bin/bash
# d55 (class 6, a water run that outgrows its disk: the sod tube on a 400 KiB tmpfs (2 MiB in the first run held all 12 times: corrected), writeInterval 7e-4 s, a tenth of its end time; corrected after the first run: foamDictionary -set had inlined the controlDict's #include): stops naming the file it could not write (FatalIOError), exit non-zero; the times written before are committed and a later restart (latestTime, on a roomy copy) continues.
. "$(dirname "$0")/../lib.sh"
sod; cd $W; tiny 400k; cp -a sod fs/sod; cd fs/sod; sed -i "s/^writeInterval .*/writeInterval   7e-4;/" system/controlDict; grep "^writeInterval\|^endTime" system/controlDict | tr "\n" " "; grep endTime system/riemannProblemDict
tryt 120 "sod on 400 KiB" rhoRiemannFoam; tail -2 $W/try.log | cut -c1-200; echo "   times: $(ls -d [0-9]* | wc -l), committed $(ls -d */.writeCommitted 2>/dev/null | wc -l)"; df -k . | tail -1
cd $W; cp -a fs/sod s2; cd s2; latest; tryt 200 "restart on a roomy disk" rhoRiemannFoam; cont; echo "   times: $(ls -d [0-9]* | wc -l), committed $(ls -d */.writeCommitted 2>/dev/null | wc -l)"
