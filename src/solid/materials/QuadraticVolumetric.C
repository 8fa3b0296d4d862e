#include "QuadraticVolumetric.H"
#include "SolidError.H"
#include "physicalBounds.H"

#include <limits>

solid::QuadraticVolumetric::QuadraticVolumetric
(
    double d0,
    double rho0,
    const std::string& context
)
:
    d0_(d0),
    rho0_(rho0)
{
    // The bulk modulus 2/d0 within [bulkModulusMin, modulusMax]
    // (physicalBounds.H; d0 = 0 is IncompressibleVolumetric)
    checkParameter
    (
        context, "d0", d0, physicalBounds::d0Min, physicalBounds::d0Max,
        "1/Pa", true
    );
    checkParameter
    (
        context, "rho0", rho0, physicalBounds::rhoMin, physicalBounds::rhoMax,
        "kg/m^3", true
    );
}


solid::VolumetricResponse solid::QuadraticVolumetric::evaluate
(
    const VolumetricInput& in,
    const double*,
    double*
) const
{
    VolumetricResponse r;
    const double t = in.theta;
    r.p = -2*(t - 1)/d0_;
    r.dpdtheta = -2/d0_;
    r.energy = (t - 1)*(t - 1)/d0_;
    // K = rho dp/drho = -theta dp/dtheta, rho = rho0/theta
    r.c2 = 2*t*t/(d0_*rho0_);
    return r;
}


solid::VolumetricResponse solid::IncompressibleVolumetric::evaluate
(
    const VolumetricInput&,
    const double*,
    double*
) const
{
    throw SolidError
    (
        SolidError::Kind::parameter,
        "incompressible (d0 = 0) volumetric law has no p(theta): the "
        "pressure is a Lagrange multiplier (implicit solver only)"
    );
}
