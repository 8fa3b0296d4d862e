#!/bin/bash
# prebuild.sh PREFIX: adv42's prebuild.sh for adv43: builds each pass's base cases once under PREFIXPASS (sourcing its
# lib.sh; each from its pass's folder) before cases run two at a time
here=$(cd "$(dirname "$0")" && pwd); cd $here/..
for p in adv35 adv36 adv37 adv38 adv39 adv40 adv41 adv42 adv43; do l=$p/lib.sh; [ -f $l ] || continue; n=${p##*/}; ADV=${1:-/tmp/adv43-}$n nice -n 10 bash -c ". $l; echo $n: \$(ls \$ADV | tr '\n' ' ')"; done
