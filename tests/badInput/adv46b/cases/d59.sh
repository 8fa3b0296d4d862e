#!/bin/bash
# d59 (class 5+1, a finished indentation with a digit of an early force.dat row changed, and a protocol row appended, restart latestTime): refused naming force.dat (the digest up to the checkpoint); never continued over the edited file.
. "$(dirname "$0")/../lib.sh"
idn; latest; f=postProcessing/indentation/force.dat; grep -vn "^#" $f | sed -n 3p; python3 - $f <<P
import sys; p=sys.argv[1]; L=open(p).read().split("\n"); k=[i for i,l in enumerate(L) if l and not l.startswith("#")][2]; s=L[k]; j=len(s)-1
while not s[j].isdigit() or s[j]=="9": j-=1
L[k]=s[:j]+str(int(s[j])+1)+s[j+1:]; open(p,"w").write("\n".join(L))
P
grep -vn "^#" $f | sed -n 3p
python3 - constant/indenterProperties <<P
import sys; p=sys.argv[1]; t=open(p).read(); i=t.index("protocol"); j=t.index(");", i); open(p,"w").write(t[:j]+"    (D load 10e-6 0.3e-6)\n"+t[j:])
P
tryt 200 "restart over an edited force.dat" cellIndentationFoam; cont; after
