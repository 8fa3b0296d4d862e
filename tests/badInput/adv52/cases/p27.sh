#!/bin/bash
# CASETIMEOUT=300
# p27 (new, class 4: exactRiemann's case-file reader, never attacked): the sod problem as a case file of "key value;"
# entries: (a) the control; (b) CRLF line ends; (c) a UTF-8 byte-order mark; (d) an entry twice in the file (pL 1e5;
# ... pL 2e5;); (e) an entry without its ';'; (f) two values in one entry (pL 1e5 2e5;); (g) a key=value argument that
# repeats a file's entry (file pL 1e5; argument pL=2e5: which wins, said?); (h) a comment // and /* */; (i) the file
# cut in the middle of a number (pL 1e). Each: the right answer or refused naming file, line and entry; another answer
# than the control's without a word = SILENT; a duplicated key taken silently = UNCLEAR (the project's rule: duplicated
# keywords are errors).
. "$(dirname "$0")/../lib.sh"
ER=$ROOT/build/bin/exactRiemann
mk() { printf 'law idealGas;\ngamma 1.4;\nCv 718;\nrhoL 1;\nuL 0;\npL 1e5;\nrhoR 0.125;\nuR 0;\npR 1e4;\nx0 0.5;\nt 5e-4;\nxMin 0;\nxMax 1;\nn 11;\n' > $W/c.case; }
er() { local l=$1; shift; tryt 30 "$l" $ER "$@"; echo "   out: $(grep -a '^#' $W/try.log | head -2 | tr -s ' ' | tr '\n' '|' | cut -c1-200) | row 5: $(grep -a -v '^#' $W/try.log | sed -n 5p | tr -s ' ' | cut -c1-100) | err: $(grep -a -i -m1 'error\|invalid\|unknown\|twice\|duplicate' $W/try.log | cut -c1-200)"; }
mk; er "(a) control" $W/c.case
mk; sed -i 's/$/\r/' $W/c.case; er "(b) CRLF" $W/c.case
mk; printf '\xef\xbb\xbf' | cat - $W/c.case > $W/c2 && mv $W/c2 $W/c.case; er "(c) a byte-order mark" $W/c.case
mk; echo 'pL 2e5;' >> $W/c.case; er "(d) pL twice (1e5, then 2e5)" $W/c.case
mk; sed -i 's/^pL 1e5;/pL 1e5/' $W/c.case; er "(e) pL without ;" $W/c.case
mk; sed -i 's/^pL 1e5;/pL 1e5 2e5;/' $W/c.case; er "(f) pL 1e5 2e5;" $W/c.case
mk; er "(g) file pL 1e5, argument pL=2e5" $W/c.case pL=2e5
mk; sed -i 's/^pL 1e5;/pL 1e5; \/\/ left pressure\n\/* a block\n comment *\//' $W/c.case; er "(h) comments" $W/c.case
mk; head -c $(( $(grep -b -o '^pL 1e5' $W/c.case | cut -d: -f1) + 5 )) $W/c.case > $W/c2; mv $W/c2 $W/c.case; er "(i) cut inside pL's number" $W/c.case
