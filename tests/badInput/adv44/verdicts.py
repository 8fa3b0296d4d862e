# verdicts.py: my verdict and note for every earlier case's output (out/P1, out/R, out/Z...) that does not simply equal its
# latest judged output (compare.py "same as" the latest), and for every case not OK now. Everything else: the verdict of
# the latest report's row (latestVerdict.py), output equal to the latest judged one after normalisation.
V = {
 "adv35_s15": ("OK", "no sigFpe: still running at the case's 280 s timeout (under load), past the old crash point, as in adv42 out/A"),
 "adv35_s16": ("OK", "no sigFpe: still running at the case's 250 s timeout, as in adv42 out/A"),
 "adv36_v01": ("OK", "the case follows an old advice (top-level times only); the restart is refused naming coupling.dat, now as 'its rows end at t = 5.99e-10 s ... cut' (adv42: 'differs in its first 7509 bytes'): how far the killed -overwrite got; the originals are aside (.0.overwritten), nothing lost"),
 "adv36_v66": ("OK", "timing (how far the killed -overwrite got); the same refusals"),
 "adv36_v69": ("OK", "process ids only"),
 "adv37_w108": ("OK", "the killed run's listing now also names interfacePatches.dat (a log the solver writes since adv42); the same refusal"),
 "adv37_w109": ("OK", "as adv43 out/preN: the second calibrateCell refused 'the work folder ... is in use: its run folder .../eval0001: it is in use by cellIndentationFoam (process N ...)'; the clean calibration rc 2"),
 "adv37_w112": ("OK", "wall times only"),
 "adv37_w113": ("OK", "killed at 4e-09 instead of 6e-09 (load); the same behaviour"),
 "adv37_w114": ("OK", "log.cellMesh 28 lines at the kill (0 before): timing; the same behaviour"),
 "adv37_w29": ("OK", "the full tmpfs hit at another write (load): the message now names it ('has 0 bytes free: No space left on device'), nothing gone, the continued logs bitwise equal to the reference (now also interfacePatches.dat)"),
 "adv38_x15": ("OK", "rank 1's message printed this time; it now names W/blast/solid/solid.h5 too (as adv43 out/preN)"),
 "adv41_q02": ("OK", "one more file listed before (the solver's interfacePatches.dat)"),
 "adv38_x55": ("UNCLEAR (low)", "unchanged (only the tmpfs's size differs from adv43 out/F): 'planeWave.py: error: a file could not be written or read: No space left on device', no file named"),
 "adv38_x70": ("OK", "process id only"),
}
