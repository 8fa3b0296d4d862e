# lib.sh (adv47a): adv46b's lib.sh (adv45's helpers of adv35-adv45 plus bd, rs, idn, ik, tryt, after, cont) with ADV
# defaulting to /tmp/adv47a-adv47a; for adv47a's variants of earlier cases (cases/*.sh)
ADV=${ADV:-/tmp/adv47a-adv47a}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv46b/lib.sh"
