#include "MieGruneisenVolumetric.H"
#include "SolidError.H"

#include <cmath>

namespace
{

eos::MieGruneisen makeEos
(
    const eos::MieGruneisen::Parameters& par,
    const std::string& context
)
{
    try
    {
        return eos::MieGruneisen(par);
    }
    catch (const eos::ParameterError& e)
    {
        throw solid::SolidError
        (
            solid::SolidError::Kind::parameter, context + ": " + e.what()
        );
    }
}

} // namespace


solid::MieGruneisenVolumetric::MieGruneisenVolumetric
(
    const eos::MieGruneisen::Parameters& par,
    double b1,
    double b2,
    const std::string& context
)
:
    eos_(makeEos(par, context)),
    b1_(b1),
    b2_(b2),
    context_(context)
{
    checkParameter(context, "b1", b1, 0, 10, "-", true);
    checkParameter(context, "b2", b2, 0, 10, "-", true);
}


void solid::MieGruneisenVolumetric::initHistory(double* h) const
{
    h[0] = 0;
    h[1] = 0;
    h[2] = 1;
    h[3] = 0;
    h[4] = 0;
}


solid::VolumetricResponse solid::MieGruneisenVolumetric::evaluate
(
    const VolumetricInput& in,
    const double* hOld,
    double* hNew
) const
{
    const auto& par = eos_.parameters();
    const double rho0 = par.rho0;
    const double G = par.Gamma0;
    const double en = hOld[0];
    const double Pn = hOld[1];
    const double tn = hOld[2];
    const double t = in.theta;
    const double rho = rho0/t;

    const eos::Status st = eos_.check(rho, en);
    if (st != eos::Status::ok || !(t > 0))
    {
        throw SolidError
        (
            SolidError::Kind::materialDomain,
            context_ + ": Mie-Grueneisen state outside its domain at "
            "theta = " + std::to_string(t) + ": "
          + eos::statusMessage(st)
        );
    }

    // Bulk viscosity with the sound speed lagged at the start of the step
    double q = 0, dqdt = 0, zeta = b1_;
    if (in.dt > 0 && (b1_ > 0 || b2_ > 0))
    {
        const double cn = std::sqrt(std::max(eos_.c2(rho0/tn, en), 0.0));
        const double L = in.length;
        const double s = t + tn;
        const double epsv = 2*(t - tn)/(in.dt*s);
        const double depsv = 4*tn/(in.dt*s*s);
        double f = -b1_*cn*L*epsv;
        double df = -b1_*cn*L*depsv;
        if (epsv < 0)
        {
            f += b2_*b2_*L*L*epsv*epsv;
            df += 2*b2_*b2_*L*L*epsv*depsv;
        }
        q = rho*f;
        // Abaqus/Explicit: xi = b1 - b2^2 L min(0, epsv)/c
        zeta = b1_ + (cn > 0 ? b2_*b2_*L*std::max(-epsv, 0.0)/cn : 0.0);
        dqdt = rho*df - rho/t*f;
    }

    // p = pc + G rho0 e, e = en + heat/rho0 - (Pn + q + p)(t - tn)/(2 rho0)
    const double pc = eos_.p(rho, 0.0);
    const double dpcdt = -eos_.dpdrho(rho, 0.0)*rho0/(t*t);
    const double dth = t - tn;
    const double a = 1 + 0.5*G*dth;
    const double eh = en + in.heat/rho0;
    const double p = (pc + G*rho0*eh - 0.5*G*(Pn + q)*dth)/a;
    const double dpdt =
        (dpcdt - 0.5*G*(Pn + q) - 0.5*G*dth*dqdt - 0.5*G*p)/a;
    const double e = eh - 0.5*(Pn + q + p)*dth/rho0;

    VolumetricResponse r;
    r.p = p + q;
    r.q = q;
    r.zeta = zeta;
    r.dpdtheta = dpdt + dqdt;
    r.energy = rho0*e;
    r.c2 = eos_.c2(rho, e);
    r.temperatureRise = eos_.T(rho, e) - par.T0;
    if (!std::isfinite(r.p) || !(r.c2 > 0))
    {
        throw SolidError
        (
            SolidError::Kind::materialDomain,
            context_ + ": Mie-Grueneisen update gives p = "
          + std::to_string(r.p) + " Pa, c^2 = " + std::to_string(r.c2)
          + " m^2/s^2 at theta = " + std::to_string(t)
        );
    }
    hNew[0] = e;
    hNew[1] = p + q;
    hNew[2] = t;
    // Work of q (heat from the shock) per reference volume
    hNew[3] = hOld[3] - 0.5*(hOld[4] + q)*dth;
    hNew[4] = q;
    return r;
}
