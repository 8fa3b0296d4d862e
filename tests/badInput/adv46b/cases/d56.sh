#!/bin/bash
# d56 (class 1, corrected after the first run: foamDictionary -set had inlined the controlDict's #include; sod tube restart to 0.0105 s after/riemannProblemDict edited (the right pressure changed) without running setRiemannProblem again): the restart continues (the dictionary is used only by setRiemannProblem) or refuses naming it; riemannError afterwards refuses or compares against the recorded problem, never against the edited one silently.
. "$(dirname "$0")/../lib.sh"
sodDone; ls system; latest; sed -i "s/^endTime .*/endTime 0.0105;/" system/controlDict; grep "^endTime" system/controlDict
sed -n "/right/,/}/p" system/riemannProblemDict | head -8 | tr "\n" " "; echo; python3 - system/riemannProblemDict <<P
import re,sys; p=sys.argv[1]; t=open(p).read(); i=t.index("right"); m=re.compile(r"(\bp\s+)([0-9.eE+-]+)").search(t, i); open(p,"w").write(t[:m.start(2)]+repr(float(m.group(2))*2)+t[m.end(2):])
P
tryt 200 "restart after riemannProblemDict edit" rhoRiemannFoam; cont; tryt 100 "riemannError after it" riemannError; tail -3 $W/try.log | cut -c1-200
