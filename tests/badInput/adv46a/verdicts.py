# verdicts.py (adv46a): my verdict and note for every earlier case's output that does not simply equal its latest judged
# output (compare.py "same as" the latest), and for every case not OK now. Everything else: the verdict of the latest
# report's row (latestVerdict.py), output equal to the latest judged one after normalisation.
V = {
 "adv45_b04": ('OK', 'as adv45 out/N after its case fix (the F column, not the time): the table through the linked case; only the wall times differ from adv45 out/B (before the case fix)'),
 "adv45_b06": ('OK', "1e308, 1e-400, 4.9e-324, 1e400 refused up front naming -values and the range; -0 and hex refused by the solver (run folders left, documented); a value twice runs twice (F 9.89986e-10 N each); adv45 out/B's F column was the time (its case fix)"),
 "adv45_b07": ('OK', "the F column now the force (adv45's case fix); the rest as adv45"),
 "adv45_b09": ('OK', "timing: this time the first sweep lost the race (s1 refused naming the live sweep's lock, s2 ran): one report of 4 lines, as adv45"),
 "adv45_b16": ('OK', "as adv45 out/Z (fixed): the random bytes' first control character is another byte this run (byte 1, 0x08), named; every odd kind named"),
 "adv45_b17": ('OK', 'timing (load 14): the 1.5 s SIGTERM landed after the study had copied its base (base, log.Allclean, an empty points/ left); the study then completes (one point, its table of 2 lines)'),
 "adv45_b19": ('OK', "(b) n/r: the space in baseCase is harmless (the point done in 11.5 s) but the case's own 60 s timeout killed the study while it drew its 8 maps (load 15; (a)'s maps took 63 s, 15:48:51-15:49:54); (a) unicode runs; (c) the study folder's space refused naming the path"),
 "adv45_b24": ('OK', "the -noRun after the interruption an error, nothing changed; the second paperFigures (not refused this time) moved the interrupted folder holding the user's note whole to averageCell.interrupted and said so (adv45 c03's behaviour), the note kept; adv45 out/B: refused"),
 "adv45_b25": ('OK', "51 of its 54 calibrateCell calls reached before runOne.sh's 300 s budget (load 16; adv45: 2 min): every one refused naming file, entry, range as adv45; F_B's 0x1p-10, 4.9e-324, 1e400 not reached (n/r)"),
 "adv45_b28": ('OK', "as adv45 (only calibrateCell's wall time in its report differs: 143 s)"),
 "adv45_b30": ('OK', "as adv45 out/N (the temporary file's pid and the line's cut at a fixed width differ)"),
 "adv45_b35": ('OK', "(a) the mesh changed through a link refused naming constant/cell.msh (changed), as adv45; (b) n/r: the restart with the identical copy was past row 4 (130 force rows, still computing) when the case's own 60 s timeout killed it (load 16-18; adv45: reached the end)"),
 "adv45_b38": ('OK', "(c) FIXED (fix19b 41fb5502, on main): the emptied options file no longer refused, the restart continues (times 1e-09 2e-09); (a) and (b) refused naming the file and now also the entry ('data'; 'coupling/scheme' read from fsiProperties.allrun)"),
 "adv45_b39": ('OK', 'as adv45 out/N; the lock files are one byte longer (a 5-digit process id)'),
 "adv45_b42": ('OK', '(a) refused naming processor1/constant/polyMesh/points (changed); printed by rank 1 this time (adv45: rank 0), the message complete (file, digests, nothing changed); (b), (c) as adv45'),
 "adv45_b46": ('OK', "the nearly full tmpfs: each run's error names the file and '0 bytes free: No space left on device' (which of the two runs hit it at create or at close swapped); rc 1, no report, the case unchanged"),
 "adv45_b41": ('OK', "(a), (c), (d) refused naming the file as adv45; (b), (e) n/r: the restarts through links to the other run's files killed by the case's own 60 s timeout while computing (load 16; adv45: rc 0 to the reference result)"),
 "adv45_b47": ('OK', 'PROJECT_DIR to another set refused naming constant/solidProperties and now also the entry materials/membrane/C10 and where it was read; the identical copy continues, as adv45'),
 "adv45_c01": ('OK', "(first run on a main: adv45's case fix came after its phase 2) each of $FOAM_CASE/constant/override, ../constant/override and the absolute path runs, the point's membrane shows the override's second branch (mu 50 Pa tau 1e-9 s)"),
 "adv45_c05": ('UNCLEAR', '(first run on a main: adv45\'s case fix came after its phase 2) (a) the relative include leaving the case refused naming it; (b) the absolute path runs; (c) #include "$FOAM_CASE/constant/set" (the file inside the case) refused \'the case\'s own parameters do not run (see /tmp/calibrateCell.X/probe/log.cellIndentationFoam)\': that log says \'Cannot open include file .../probe/constant/set\': calibrateCell\'s probe copy holds only cell.msh, indenterProperties, solidProperties of constant/; a valid case cannot be calibrated and the message blames its parameters; the /tmp/calibrateCell.X folders of (a) and (c) are left'),
 "adv45_c04": ('OK', "as adv45 out/Z (only the sweep's wall time differs)"),
}
