#include "NeoHookean.H"
#include "SolidError.H"
#include "physicalBounds.H"

#include <cmath>
#include <limits>

solid::NeoHookean::NeoHookean(double C10, const std::string& context)
:
    C10_(C10)
{
    checkParameter
    (
        context, "C10", C10, 0, physicalBounds::modulusMax, "Pa", true
    );
}


void solid::NeoHookean::evaluate
(
    const Mat3& C,
    double,
    const double*,
    double*,
    IsoResponse& r
) const
{
    using namespace tensor;
    const double J2 = C.determinant();
    const double Jm23 = std::pow(J2, -1.0/3.0);
    const Mat3 Ci = C.inverse();
    const Mat3 I = Mat3::Identity();
    const double I1 = C.trace();
    const double mu = 2*C10_;

    r.psi = C10_*(Jm23*I1 - 3.0);
    r.S = mu*Jm23*(I - I1/3.0*Ci);
    r.CC = mu*Jm23*
    (
        -2.0/3.0*(dyad(I, Ci) + dyad(Ci, I))
      + 2.0/9.0*I1*dyad(Ci, Ci)
      + 2.0/3.0*I1*symProduct(Ci)
    );
}


void solid::NeoHookean::stress
(
    const Mat3& C,
    double,
    const double*,
    double*,
    IsoResponse& r
) const
{
    const double Jm23 = std::cbrt(1.0/C.determinant());
    const double I1 = C.trace();
    r.psi = C10_*(Jm23*I1 - 3.0);
    r.S = 2*C10_*Jm23*(Mat3::Identity() - I1/3.0*C.inverse());
}
