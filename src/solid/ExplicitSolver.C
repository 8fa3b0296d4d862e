#include "ExplicitSolver.H"
#include "SolidError.H"

#include <cmath>

solid::ExplicitSolver::ExplicitSolver
(
    Model& model,
    const ExplicitSettings& settings
)
:
    model_(model),
    set_(settings)
{
    Model& m = model_;
    const Mesh& mesh = m.mesh();
    for (int e = 0; e < mesh.nElements(); ++e)
    {
        if (m.material(e).volumetric().isConstraint())
        {
            throw SolidError
            (
                SolidError::Kind::parameter,
                "explicit solver: region '"
              + mesh.regionNames[mesh.region[e]] + "' (material '"
              + m.material(e).name() + "') is incompressible (d0 = 0); "
                "the explicit solver needs d0 > 0 or volumetric "
                "mieGruneisen"
            );
        }
    }
    checkParameter("explicit solver", "safety", set_.safety, 0, 1, "-");
    m.condensePressure(true);
    fixed_ = m.prescribedDofs();
    invMass_ = m.lumpedMass().cwiseInverse();
    m.assemble(m.u, m.pressure, m.time, 0, false, asm_);
    m.commit();
    fint_ = asm_.fint;
    fext_ = asm_.fext;
    a_ = (fext_ - fint_).cwiseProduct(invMass_);
    for (int d : fixed_) a_(d) = 0;
    stableDt_ = asm_.stableDt;
    dt_ = set_.fixedDt > 0 ? set_.fixedDt : set_.safety*stableDt_;
    energy_.kinetic = 0.5*m.v.dot(m.lumpedMass().cwiseProduct(m.v));
    energy_.internal = asm_.energy;
    energy_.initial = energy_.kinetic + energy_.internal;
}


void solid::ExplicitSolver::updateEnergy
(
    const Eigen::VectorXd& du,
    const Eigen::VectorXd& fint,
    const Eigen::VectorXd& fext
)
{
    energy_.internalWork += 0.5*du.dot(fint_ + fint);
    energy_.externalWork += 0.5*du.dot(fext_ + fext);
    // Reactions at prescribed dofs: r = f_int - f_ext (quasi-static part)
    for (int d : fixed_)
    {
        energy_.externalWork +=
            0.5*du(d)*((fint_(d) - fext_(d)) + (fint(d) - fext(d)));
    }
}


double solid::ExplicitSolver::step()
{
    Model& m = model_;
    const double dt = dt_;
    if (set_.fixedDt > 0 && dt > stableDt_)
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "explicit solver: fixed time step " + std::to_string(dt)
          + " s exceeds the stable time step " + std::to_string(stableDt_)
          + " s"
        );
    }
    const double t1 = m.time + dt;
    const Eigen::VectorXd u0 = m.u;
    Eigen::VectorXd vh = m.v + 0.5*dt*a_;
    m.u += dt*vh;
    m.applyDirichlet(m.u, t1);
    for (int d : fixed_) vh(d) = (m.u(d) - u0(d))/dt;

    try
    {
        m.assemble(m.u, m.pressure, t1, dt, false, asm_);
    }
    catch (const SolidError& e)
    {
        m.revert();
        m.u = u0;
        throw SolidError
        (
            e.kind(), "explicit step at t = " + std::to_string(m.time)
          + " s (dt = " + std::to_string(dt) + " s): " + e.what()
        );
    }
    Eigen::VectorXd a = (asm_.fext - asm_.fint).cwiseProduct(invMass_);
    for (int d : fixed_) a(d) = 0;
    m.v = vh + 0.5*dt*a;
    for (int d : fixed_) m.v(d) = vh(d);
    updateEnergy(m.u - u0, asm_.fint, asm_.fext);
    fint_ = asm_.fint;
    fext_ = asm_.fext;
    a_ = a;
    m.time = t1;
    m.commit();
    ++steps_;

    energy_.kinetic = 0.5*m.v.dot(m.lumpedMass().cwiseProduct(m.v));
    energy_.internal = asm_.energy;
    energy_.dissipated = asm_.dissipated;
    energy_.shockHeat = asm_.shockHeat;
    energy_.viscousHeat = asm_.viscousHeat;
    stableDt_ = asm_.stableDt;
    dt_ = set_.fixedDt > 0 ? set_.fixedDt : set_.safety*stableDt_;
    return dt;
}


void solid::ExplicitSolver::advanceTo(double tEnd)
{
    while (model_.time < tEnd*(1 - 1e-12))
    {
        if (model_.time + dt_ > tEnd) dt_ = tEnd - model_.time;
        step();
    }
}
