#!/bin/bash
# table.sh [-t] DIR... (adv54, as adv53's): adv52's mkTable.py, called from its folder (not copied), reading my
# verdicts.txt and my out/ (its `here` is the folder of __file__, set to this folder)
here=$(cd "$(dirname "$0")" && pwd)
/usr/bin/python3 - "$@" <<PY
import sys
sys.argv = ['mkTable.py'] + sys.argv[1:]
src = open('$here/../adv52/mkTable.py').read()
exec(compile(src, '$here/../adv52/mkTable.py', 'exec'), {'__file__': '$here/verdicts.txt', '__name__': '__main__'})
PY
