#!/bin/bash
# The Courant limit of the fluid solver, measured (docs/reliability.md,
# "adv32's rows closed by fix19k"): the 50 MPa water shock tube
# (tutorials/verification/waterShock50MPa) run by rhoRiemannFoam at each
# maxCo given (default 0.5 1), riemannError's L1 errors against the exact
# solution printed. Not a ctest (a measurement); usage:
#   bash tests/verification/courantLimit.sh [maxCo ...]
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for co in ${@:-0.5 1}
do
    c=$work/maxCo$co
    mkdir "$c"
    cp -r "$root/tutorials/verification/waterShock50MPa"/{0.orig,system,constant} "$c"/
    rm -rf "$c/constant/polyMesh"
    sed -i "s/^maxCo .*/maxCo           $co;/" "$c/system/controlDict"
    (cd "$c" && cp -r 0.orig 0 && blockMesh > log.blockMesh 2>&1 \
        && setRiemannProblem > log.set 2>&1)
    if (cd "$c" && rhoRiemannFoam > log.solver 2>&1)
    then
        echo "maxCo $co:"
        (cd "$c" && riemannError 2>&1 | grep -E 'L1 errors|star state')
    else
        echo "maxCo $co: rhoRiemannFoam failed: $(grep -A1 FATAL "$c/log.solver" | tail -1)"
    fi
done
