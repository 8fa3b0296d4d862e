# verdicts.py (adv45): my verdict and note for every earlier case's output (out/N, out/A44, out/35, phase 2's) that does not
# simply equal its latest judged output (compare.py "same as" the latest), and for every case not OK now. Everything else:
# the verdict of the latest report's row (latestVerdict.py), output equal to the latest judged one after normalisation.
V = {
 "adv35_o22": ("OK", "fix19z's range message ('entry 'heightFraction' = 1.5 - is outside the valid range (0, 1) -'); refused as before, nothing changed"),
}
