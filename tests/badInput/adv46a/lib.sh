# lib.sh (adv46a): adv45's lib.sh (all helpers of adv35-adv45) with ADV defaulting to /tmp/adv46a-adv46a; for the few
# variants of earlier cases that adv46a wrote while re-running them (cases/e*.sh)
ADV=${ADV:-/tmp/adv46a-adv46a}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv45/lib.sh"
