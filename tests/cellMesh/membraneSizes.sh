#!/bin/bash
# cellMesh on tests/badInput/cellMeshDict with membraneSize (and
# contactSize) edited: whether gmsh makes elements (docs/reliability.md,
# adv32 cm17, fix19k). Not a ctest (a measurement); usage:
#   bash tests/cellMesh/membraneSizes.sh ["membraneSize contactSize" ...]
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ $# -gt 0 ] || set -- "4e-7 4e-7" "3e-7 4e-7" "2e-7 4e-7" "1e-7 4e-7" \
    "1e-8 4e-7" "2e-7 2e-7"
for sizes in "$@"
do
    read -r ms cs <<< "$sizes"
    c=$work/case
    rm -rf "$c"
    mkdir -p "$c/system" "$c/constant"
    cp "$root/tests/badInput/cellMeshDict" "$c/system/"
    sed -i "s/^membraneSize .*/membraneSize    $ms;/; s/^contactSize .*/contactSize     $cs;/" \
        "$c/system/cellMeshDict"
    (cd "$c" && nice -n 10 cellMesh > log 2>&1)
    echo "membraneSize $ms m, contactSize $cs m: exit $?," \
        "$(grep -m1 '^ *total ' "$c/log" | awk '{print $2}') elements"
done
