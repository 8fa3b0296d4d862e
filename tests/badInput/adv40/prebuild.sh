#!/bin/bash
# prebuild.sh: builds each earlier pass's base cases once under /tmp/adv40-PASS (sourcing its lib.sh), before cases run two at a time
cd "$(dirname "$0")/.."
for p in adv35 adv36 adv37 adv38 adv39; do ADV=/tmp/adv40-$p nice -n 10 bash -c ". $p/lib.sh; echo $p: \$(ls \$ADV)"; done
