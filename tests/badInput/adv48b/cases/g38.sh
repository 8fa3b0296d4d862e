#!/bin/bash
# g38 (class 4, interface measures at their edges) the prepared preview, endTime 2e-11, constant/solidProperties: interfacePatchLength 0, 1 (1 m, longer than every interface), 1e-300, nan; interfaces ((membrane membrane)), ((cytoplasm membrane)) (the pair reversed); interfacePlaces' point 'top' at (nan 0 0) and at (1 1 0) (1 m away): refused naming the entry and why, or accepted with the measure meaningful (said); never a crash.
. "$(dirname "$0")/../lib.sh"
blast; short
each constant/solidProperties "interfacePatchLength 0" "interfacePatchLength 1" "interfacePatchLength 1e-300" "interfacePatchLength nan" "interfaces ((membrane membrane))" "interfaces ((cytoplasm membrane) (cytoplasm nucleus))" "top (nan 0 0)" "top (1 1 0)" -- cellBlastFoam
