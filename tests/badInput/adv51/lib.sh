# lib.sh (adv51): adv50b's lib.sh (and through it every helper of adv35-adv50b: bd, idn, ik, q, qrun, pbd, sbd, blast,
# latest, restart0, sums, changed, tryt, msg?, sete, dupe, fsiSet (adv50b's corrected one: inside coupling{} only), mdir,
# mset, cm, qm, cmk, pwd0, prj, iw, vals, sb, mv_, killAll ...) plus the helpers of adv48a's lib.sh (dmgf, setv, sig, setb,
# cutf) and adv49a's (msg, subset, setbb), read from their files without their first lines (as adv50a's lib.sh does).
# runOne.sh's ADV=<prefix>adv51 is mapped to <prefix>adv50b, which adv50b's lib.sh maps on to <prefix>adv47b: every base
# lies there (prebuild.sh). At the case's exit $W is removed (adv50b's trap).
# Mine:
#   hdr FILE       the FoamFile header of FILE unchanged? (prints "header kept" or "HEADER CHANGED") against $W/hdr.FILE
#                  saved by hdr0 FILE: every edit of mine is checked to touch only the entry it means
ADV=${ADV:-/tmp/adv51-adv51}; ADV=${ADV%adv51}adv50b
here51_=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
. "$here51_/../adv50b/lib.sh"
. <(grep -v '^ADV=\|^\. ' "$here51_/../adv48a/lib.sh")
. <(grep -v '^ADV=\|^\. ' "$here51_/../adv49a/lib.sh")
hdr0() { sed -n '/^FoamFile/,/^}/p' "$1" > "$W/hdr.$(echo $1 | tr / _)"; }
hdr() { if sed -n '/^FoamFile/,/^}/p' "$1" | cmp -s - "$W/hdr.$(echo $1 | tr / _)"; then echo "   $1: header kept"; else echo "   $1: HEADER CHANGED"; fi; }
