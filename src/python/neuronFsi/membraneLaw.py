"""The transparent cell of the blast scenes: a case's membrane given
water's Mie-Grueneisen law instead of its quadratic law (paper eq. 2), as
nucleus and cytoplasm already have. With every region water to its shear
moduli (1e2 Pa against K = 2.1 GPa), the exact answer of the scene is the
1D water plane wave, at rest after the pulse (docs/results/
blastPlaneWave.md "The transparent cell", docs/results/blast3D.md "What
makes the rest flow in 3D"). Used by the bench scripts that run it."""

import sys

# The membrane's entries as the blast tutorials write them, and water's law
# (constant/thermophysicalProperties of the tutorials; SI units).
QUADRATIC = """volumetric  quadratic;  // Psi_vol = (J - 1)^2/d0 (paper eq. 2)
        d0          9.5125e-10; // 2/K [1/Pa], K = 1000 x 1450^2 Pa"""
WATER = ("volumetric  mieGruneisen;\n"
         "        C0 1450; s 1.99; Gamma0 0.1; Cv 4184; T0 293.15;")


def setWaterLaw(path):
    """Replace the membrane's quadratic law in the solidProperties file
    `path` by water's law; raise ValueError naming the file if the
    tutorials' quadratic entry is not there exactly once."""
    with open(path) as f:
        s = f.read()
    n = s.count(QUADRATIC)
    if n != 1:
        raise ValueError("%s: the membrane's quadratic law (volumetric "
                         "quadratic; d0 9.5125e-10) found %d times, expected "
                         "once" % (path, n))
    with open(path, "w") as f:
        f.write(s.replace(QUADRATIC, WATER))


def main(argv=None):
    """python3 -m neuronFsi.membraneLaw water FILE"""
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 2 or argv[0] != "water":
        sys.exit("usage: python3 -m neuronFsi.membraneLaw water "
                 "constant/solidProperties")
    try:
        setWaterLaw(argv[1])
    except (OSError, ValueError) as e:
        sys.exit("neuronFsi.membraneLaw: %s" % e)


if __name__ == "__main__":
    main()
