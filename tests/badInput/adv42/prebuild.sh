#!/bin/bash
# prebuild.sh PREFIX: adv41's prebuild.sh with adv42's default prefix: builds each pass's base cases once under PREFIXPASS
# (sourcing its lib.sh) before cases run two at a time
cd "$(dirname "$0")/.."; for p in adv35 adv36 adv37 adv38 adv39 adv40 adv41 adv42; do [ -f $p/lib.sh ] || continue; ADV=${1:-/tmp/adv42-}$p nice -n 10 bash -c ". $p/lib.sh; echo $p: \$(ls \$ADV | tr '\n' ' ')"; done
