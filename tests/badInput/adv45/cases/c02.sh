#!/bin/bash
# c02 (phase 2, class 4, dictionaries after fix19b's UTF-8 reading; from fix19b-fixed.md's b16 line only): pulseStudyDict (a) beginning with a UTF-8 byte-order mark, (b) in UTF-16 (as some Windows editors save), (c) with a UTF-8 "µm" in a comment, (d) with a Latin-1 byte inside the threshold's source string, (e) CRLF line ends: each read (a comment or an encoding mark is no input) or refused naming the file (and line/byte), never a traceback; the study then runs its point where read (nProcs 0 is set in (a)-(d) so that a read dictionary is refused by nProcs, not run)?
. "$(dirname "$0")/../lib.sh"
study; cp system/pulseStudyDict ../d.orig; D=system/pulseStudyDict
for k in bom utf16 utf8mu latin1src crlf; do cp ../d.orig $D; [ $k != crlf ] && setStudy nProcs 0
  case $k in bom) printf '\xef\xbb\xbf' | cat - $D > ../t && mv ../t $D;; utf16) iconv -f UTF-8 -t UTF-16 $D > ../t && mv ../t $D;; utf8mu) printf '// a size in \xc2\xb5m\n' >> $D;; latin1src) sed -i 's/source      "Bain and Meaney 2000/source      "Bain and Meaney 2000 (\xe9d.)/' $D;; crlf) sed -i 's/$/\r/' $D;; esac
  timeout -s KILL 150 pulseStudy -case . > ../log.s 2>&1; echo "($k) rc=$? | $(grep -a -m1 -i 'error\|Traceback\|done' ../log.s | cut -c1-240)"; rm -rf postProcessing; done
