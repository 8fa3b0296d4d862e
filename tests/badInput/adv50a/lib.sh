# lib.sh (adv50a): adv49b's lib.sh (and through it adv48b's, adv47b's ... adv35's helpers and adv49b's sbd, xbd, mbd, mdir,
# mset, cm, fset, fresh, rs6, e6, cmp6, away) with ADV mapped to PREFIXadv47b, where adv48a's, adv48b's and adv49b's
# prebuild.sh (called with this pass's prefix) put every base; plus the helpers of adv48a's lib.sh (dmgf, setv, sig, setb,
# cutf) and adv49a's (msg, subset, setbb), read from their files without their first lines (sourcing them whole would
# source the chain adv47b ... adv35 a second time). runOne.sh's ADV=<prefix>adv50a is mapped to <prefix>adv49b first.
# Mine:
#   cell3 F I A B C   cell I of the ascii or binary vector field F set to (A B C) (fset for a vector, internal field)
#   ulpEdge LAW ...   prints the edge values computed by python (see ulpEdge.py)
ADV=${ADV:-/tmp/adv50a-adv50a}; ADV=${ADV%adv50a}adv49b
here50_=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
. "$here50_/../adv49b/lib.sh"
. <(grep -v '^ADV=\|^\. ' "$here50_/../adv48a/lib.sh")
. <(grep -v '^ADV=\|^\. ' "$here50_/../adv49a/lib.sh")
