#!/bin/bash
# CASETIMEOUT=400
# n11 (new, class 4/2: tutorials/paper's Allrun options, the corpus has none): a copy of tutorials/paper ($W/paper; runs
# it misses go to its own postProcessing/runs, killed after 40 s): (a) -output twice (-output A -output B), (b) -results
# twice, (c) -output an existing regular file, (d) -results a folder that is not a tutorials folder ($W/empty), (e)
# -results a file, (g) an unknown option (-outptu) and an option without its folder.
# Each refused rc != 0 naming the option before anything is run or written (a repeated option is refused by every tool of
# ours: reliability.md class 4); never the file given as -output replaced.
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/paper" $W/paper; mkdir -p $W/empty $W/A $W/B; echo "user's file" > $W/file.txt; cd $W/paper
pa() { local l=$1; shift; tryt 40 "$l" ./Allrun "$@"; killIn $W; sleep 1; killIn $W; echo "   out: $(grep -av '^ *$' $W/try.log | head -3 | tr '\n' '|' | cut -c1-300) | runs started: $(ls postProcessing/runs 2>/dev/null | tr '\n' ' ') | A: $(ls $W/A | tr '\n' ' ') B: $(ls $W/B | tr '\n' ' ') | file.txt: $(head -c 20 $W/file.txt)"; rm -rf postProcessing log.paperFigures; }
pa "(a) -output A -output B" -output $W/A -output $W/B
pa "(b) -results twice" -results "$ROOT/tutorials" -results $W/empty
pa "(c) -output an existing file" -output $W/file.txt
pa "(d) -results a folder that is not a tutorials folder" -results $W/empty
pa "(e) -results a file" -results $W/file.txt
pa "(g) -outptu A" -outptu $W/A
pa "(g) -output without its folder" -output
