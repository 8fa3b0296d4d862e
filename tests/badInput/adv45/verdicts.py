# verdicts.py (adv45): my verdict and note for every earlier case's output (out/N, out/A44, out/35, phase 2's) that does not
# simply equal its latest judged output (compare.py "same as" the latest), and for every case not OK now. Everything else:
# the verdict of the latest report's row (latestVerdict.py), output equal to the latest judged one after normalisation.
V = {
 "adv35_o22": ("OK", "fix19z's range message ('entry 'heightFraction' = 1.5 - is outside the valid range (0, 1) -'); refused as before, nothing changed"),
 "adv35_s15": ("OK", "n/r: under load 22 the run reached only t = 0.118 s of row A at the case's 280 s timeout (the old sigFpe was at 0.177 s); no signal; past it in adv44 P1 and adv42"),
 "adv35_s16": ("OK", "n/r: under load 22 the run reached t = 0.08 s at the case's timeout; no signal (as adv44 P1, which got further)"),
 "adv35_s20": ("OK", "the case's 250 s timeout reached in row B under load 22 (adv44: finished C1); no signal"),
 "adv36_v01": ("OK", "timing: the -overwrite SIGKILLed before it moved anything (load): the times stay, the restart refused as having nothing to compute (endTime), the later restart continues, lost 0"),
 "adv36_v38": ("OK", "timing: the Allrun still alive when looked at; the same lock behaviour"),
 "adv36_v66": ("OK", "timing: the killed -overwrite got to 2.5e-11 s instead of 2.1e-9 s; the restart refused naming coupling.dat as cut, as before in kind"),
 "adv36_v69": ("OK", "timing: the Allrun's shell still alive when looked at; the lock names the live solver as before"),
 "adv36_v77": ("OK", "timing: the -overwrite was killed after its first checkpoint this time (nothing left aside); the restart refused naming the changed maxDepthIncrement (adv44: killed before, the refusal named the .overwritten files)"),
 "adv37_w108": ("UNCLEAR (low)", "w86's pattern: only rank 1's refusal printed, '5 result files or folders that this run would replace:' followed by no file (they are rank 0's: solid.h5, the postProcessing folders); adv44 P1 printed rank 0's complete message"),
 "adv37_w112": ("OK", "timing: under load the user's edit (1.5 s after the start) landed before the sweep took its base copy: all three runs read holdGrowth 1.2, no note needed, the table of one case"),
 "adv37_w109": ("OK", "the second calibrateCell refused (rc 1) while the orphaned forward run of the killed one went on (gone by t+16 s); the clean calibration then ran past the case's 300 s budget under load 20 (killed by runOne.sh, '[case exit 137]'): n/r for the fit's comparison, no hang of ours"),
 "adv37_w113": ("OK", "n/r: under load the kill landed after the Allrun had finished (times to 8e-9, rc 0)"),
 "adv37_w114": ("OK", "n/r: under load the kill landed after cellMesh had finished; the Allrun then ran to its end (rc 0)"),
 "adv37_w29": ("OK", "the full tmpfs's numbers; interfacePlaces.dat (lad17's log) compared too, bitwise equal"),
 "adv37_w86": ("OK", "rank 0's complete message printed this time (as adv42 out/C); adv44 Z2 had rank 1's incomplete one (UNCLEAR low, fix19b part 1)"),
}
