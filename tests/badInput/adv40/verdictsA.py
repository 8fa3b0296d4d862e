# Phase A verdicts (main 79a71b4): (verdict now, note) for every case judged other than "OK, output as the last judged
# run's" - i.e. every case not OK now, every case whose verdict differs from the pass that made it, and the outputs that
# differ from the last judged run's. Everything else: OK (output equal to the last judged run's after compareA.py's
# normalisation: case folders, process ids, dates, durations, line numbers of the sources).
A = {
 # ---- not OK now: new in this re-run
 "adv35_c16": ("DATALOSS", "the two Allruns at once behave (second refused naming the first, first rc 0); but the case's own `cellBlastFoam -postProcess` (before its restart check) rewrote postProcessing/fluidProbes/0/p from 6041 to 791 bytes (the run's 45 water-probe rows replaced by 4), exit 0, nothing said; the restart is then refused naming the cut log. Same root as z01 (phase B). Was rc 0 at the restart in adv35/adv36: the cut went unseen then (no log digests)"),
 "adv37_w109": ("UNCLEAR", "REGRESSION in outcome (OK in adv37), timing-dependent (1 of 2 runs: out/A, out/A2): calibrateCell SIGKILLed, its forward run orphaned in <work>/eval0001, the same command again: it stopped at once with 'calibrateCell.py: error: the program 'restart.h5.tmp' is not found on PATH: build the project (./Allwmake) and source its etc/bashrc first', rc 1, no fit. Cause (read in the code): forwardModel._make_run_dir removes eval0001 with shutil.rmtree while the orphan still writes there (forward runs are started with signals.call, not through neuronFsi.caseRuns, so no marker and no checkNoEarlierRun); the orphan's restart.h5.tmp vanished during the rmtree, and neuronFsi.script.message words any FileNotFoundError whose name has no '/' as a missing program. The second run (out/A2) ended like adv37's: the orphan ended by the rmtree, the fit equal to a clean calibration's"),
 "adv38_x15": ("UNCLEAR", "low; the -overwrite from the middle time on 2 ranks is refused as before, but the message the user sees is rank 1's, which names no file: 'its state continues (the time's uniform/ state names a step of it)' - the path of solid/solid.h5 (on the master's side) is empty; adv38 saw rank 0's message, which names it. Which rank prints first is chance (w02 shows both, rank 1's listing no file either)"),
 # ---- not OK now: open rows of earlier passes, output unchanged (fix19u's rows)
 "adv38_x05": ("UNCLEAR", "low; unchanged: a stale lock whose pid is the new run's own is refused naming itself (fix19u row 6)"),
 "adv38_x14": ("UNCLEAR", "low; unchanged: -overwrite with startTime 1.5e-09 (no such directory) 'has no uniform/time'; startTime -1e-09: OpenFOAM's 'cannot find file' (fix19u row 4)"),
 "adv38_x23": ("UNCLEAR", "low; unchanged: the same #include twice: 'lines 50 and 50' of the included file, not the two #include lines (fix19u row 5)"),
 "adv38_x24": ("UNCLEAR", "low; unchanged: #remove then the entry again refused as a duplicate (fix19u row 5)"),
 "adv38_x28": ("UNCLEAR", "low; unchanged: a log gzipped away refused as 'its rows end at t = (none)', not as missing (fix19u row 6)"),
 "adv38_x54": ("UNCLEAR", "unchanged: fresh indentation on a full disk: 'cannot create HDF5 file .../solid.h5.tmp' without the full-disk note; the empty force.dat left blocks the next start (fix19u row 1)"),
 "adv38_x55": ("UNCLEAR", "low; unchanged: planeWave on a full disk: 'a file could not be written or read: No space left on device', no file named (fix19u row 6)"),
 "adv38_x65": ("UNCLEAR", "low; as adv39: Allrun -solidSubcycles range [1, inf) against fsiProperties' [1, 1000] (fix19u row 3)"),
 "adv39_y06": ("UNCLEAR", "low; unchanged: a serial run's own times called 'reconstructed into the case' (fix19u row 2)"),
 "adv39_y07": ("UNCLEAR", "low; unchanged (rank 1 printed first this time): same wording as y06 (fix19u row 2)"),
 "adv39_y09": ("UNCLEAR", "low; unchanged: scale 1000.001 printed as 1000 (fix19u row 3)"),
 "adv39_y10": ("UNCLEAR", "low; unchanged: 0/T '.*' respelled per patch refused as a change (fix19u row 5)"),
 "adv39_y15": ("UNCLEAR", "low; unchanged: '+2'/'0x2' refused without the range (fix19u row 3)"),
 "adv39_y17": ("UNCLEAR", "low; unchanged: a table moved to a tableFile refused as changed (fix19u row 5)"),

 # ---- OK now, output differs from every earlier one (reviewed), or the premise was not met this time
 "adv35_s15": ("OK", "no sigFpe: still running at the case's 280 s timeout (t = 0.453 s of row A, slower under a load average of 10), past the old crash point 0.177 s"),
 "adv35_s16": ("OK", "no sigFpe: still running at the case's 250 s timeout (t = 0.349 s), past the old crash point 0.176 s"),
 "adv36_v66": ("OK", "the case follows the OLD advice (a loop over the top folder's .*.overwritten only): the function objects' folders are not put back and the restart is refused naming coupling.dat 'edited or damaged'; the current advice (find -depth ..., v04, x17) restores them. Nothing silent, nothing lost"),
 "adv36_v69": ("OK", "as adv37 phase 2 (process ids only differ)"),
 "adv36_v03": ("OK", "premise differs (load average ~10): the SIGTERMed -overwrite had not reached its first checkpoint; the restart is refused naming every result moved aside (.<name>.overwritten), as documented"),
 "adv36_v11": ("OK", "premise not met under load: none of the five kills reached the first write; the restart is refused as a new start over partial results, naming them (documented)"),
 "adv36_v56": ("OK", "the case's 150 s timeout reached while progressing (t = 1.96 s of the 3-s hold; its sed now lengthens the hold row, which it did not in adv36: that run ended at 2.1 s); no signal"),
 "adv37_w02": ("OK", "premise not met under load: rank 1 was killed before the first write, so the 2-rank restart is refused as a new start over partial outputs (documented); rank 0's message lists them, rank 1's (printed first) lists none (x15's pattern)"),
 "adv37_w13": ("OK", "the 2-rank run went to 8e-09 with rc 0: decomposePar -force ended (02:51:26.7) before the ranks had written anything (first time 02:51:35.9); not the race adv38 phase 2 judged"),
 "adv37_w108": ("OK", "as adv38 phase 2; rank 0's message printed this time (it names the files)"),
 "adv37_w112": ("OK", "as adv37 phase 2 (the wall times differ)"),
 "adv37_w113": ("OK", "as adv37 phase 2 (killed at 2e-09 instead of 3e-09; the runStep messages now give the exit status)"),
 "adv37_w114": ("OK", "as adv37 phase 2 (log.cellMesh empty at the kill this time)"),
 "adv37_w116": ("OK", "as adv37 phase 2 (the runStep messages now give the exit status)"),
 "adv37_w18": ("OK", "as adv37 phase 2 ('initial conditions' now 'initial boundary condition')"),
 "adv38_x33": ("OK", "as adv39 phase A (the writeGuard message reworded for the closing 'end' line)"),
 "adv38_x43": ("OK", "premise met this time (killed inside planeWave -inflow): the re-run says it was stopped and runs it again (as adv39 y18)"),
 "adv38_x46": ("OK", "the case follows an older advice (removes only log.cellBlastFoam.running, runs the solver by hand into log.hand); the next ./Allrun now refuses, saying log.cellBlastFoam has no End line and no exit status; 8e-09/p equal to the uninterrupted Allrun. See z31 for the current advice followed word for word"),
 "adv39_y12": ("OK", "(d) now moved aside as incomplete (closing 'end' line), continues from 1e-09 (the lead's fix after adv39)"),
 "adv39_y16": ("OK", "moved aside as 2e-09.incomplete, continues from 1e-09"),
 "adv39_y20": ("OK", "moved aside on both ranks (processor0/2e-09.incomplete), continues from 1e-09"),
}
