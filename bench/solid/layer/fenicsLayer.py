#!/usr/bin/python3
"""Independent solution of the layer indentation with FEniCS legacy (dolfin).

Axisymmetric (r-z) bonded neo-Hookean layer of radius W and thickness H
(bottom z = 0 bonded, side r = W free, axis r = 0), a rigid frictionless
sphere of radius R pressed into its top from depth 0 to the last of the
given depths. Taylor-Hood P2/P1 mixed displacement-pressure elements on
triangles, total Lagrangian, strain energy per reference volume

    Psi(u, p) = mu/2 (I1bar - 3) + p (J - 1) - p^2/(2 K)

(K = inf: exactly incompressible, J = 1 weakly; finite K: the CalculiX
NEO HOOKE energy C10 (I1bar - 3) + (J - 1)^2/D1 with C10 = mu/2,
D1 = 2/K once p is eliminated). Contact: penalty on the reference top
surface, energy (k/2) int <-g>^2 dA0 with g = |x - c| - R the gap of the
current point x to the sphere centre c; the force on the body is the
integral of k <-g> (-n_z) dA0 (n the sphere's outward normal). The penalty
error is O(1/k): run.py extrapolates it away from k and 4 k.

The mesh: the unit square with n x m cells of two triangles mapped by
layerMesh.mapPoints (the graded map of all three codes: cells uniform in
r <= rFine, growing beyond and away from the top); level L has
n = n0 2^L, m = m0 2^L (the same map, so Richardson extrapolation in h
applies).

Units: um, Pa; force Pa um^2 = 1 pN. Prints one JSON object per depth.

Needs dolfin 2019 for Python 3 (Debian/Ubuntu: apt-get install
python3-dolfin), run with /usr/bin/python3.
"""
import argparse
import json
import math
import sys
import time

try:
    import dolfin as df
    import ufl
except ImportError:
    sys.exit("fenicsLayer.py: no dolfin module for this python (" +
             sys.executable + "): install FEniCS legacy with "
             "'apt-get install python3-dolfin' and run /usr/bin/python3")
import numpy as np

import layerMesh


def mesh(W, H, n0, m0, level, rFine):
    n, m = n0*2**level, m0*2**level
    msh = df.RectangleMesh(df.Point(0, 0), df.Point(1, 1), n, m,
                           "right/left")
    xy = msh.coordinates()
    xy[:, 0], xy[:, 1] = layerMesh.mapPoints(xy[:, 0], xy[:, 1], W, H,
                                             rFine)
    return msh


def solve(args):
    W, H, R, mu = args.W, args.H, args.R, args.mu
    K = math.inf if args.K <= 0 else args.K
    msh = mesh(W, H, args.n0, args.m0, args.level, args.rFine)
    P2 = df.VectorElement("CG", msh.ufl_cell(), 2)
    P1 = df.FiniteElement("CG", msh.ufl_cell(), 1)
    V = df.FunctionSpace(msh, df.MixedElement([P2, P1]))
    w = df.Function(V)
    u, p = df.split(w)
    x0 = df.SpatialCoordinate(msh)
    r = x0[0]

    tol = 1e-9
    bottom = df.CompiledSubDomain("on_boundary && near(x[1], 0, t)", t=tol)
    axis = df.CompiledSubDomain("on_boundary && near(x[0], 0, t)", t=tol)
    top = df.CompiledSubDomain("on_boundary && near(x[1], H, t)", H=H,
                               t=tol)
    bcs = [df.DirichletBC(V.sub(0), df.Constant((0, 0)), bottom),
           df.DirichletBC(V.sub(0).sub(0), df.Constant(0), axis)]
    facets = df.MeshFunction("size_t", msh, 1, 0)
    top.mark(facets, 1)
    bottom.mark(facets, 2)
    ds = df.Measure("ds", domain=msh, subdomain_data=facets,
                    metadata={"quadrature_degree": args.quadrature})
    dx = df.Measure("dx", domain=msh, metadata={"quadrature_degree": 6})

    # Axisymmetric deformation gradient (r, theta, z)
    F = ufl.as_matrix([[1 + u[0].dx(0), 0, u[0].dx(1)],
                       [0, 1 + u[0]/r, 0],
                       [u[1].dx(0), 0, 1 + u[1].dx(1)]])
    J = ufl.det(F)
    I1bar = J**(-2.0/3.0)*ufl.tr(F.T*F)
    psi = mu/2*(I1bar - 3) + p*(J - 1)
    if math.isfinite(K):
        psi -= p**2/(2*K)
    depth = df.Constant(0.0)
    k = df.Constant(args.penalty)
    cz = H + R - depth
    x = x0 + u
    dist = ufl.sqrt(x[0]**2 + (x[1] - cz)**2)
    gap = dist - R
    pen = (abs(gap) - gap)/2                # <-g>
    twoPi = 2*math.pi
    Pi = twoPi*psi*r*dx + twoPi*0.5*k*pen**2*r*ds(1)
    res = df.derivative(Pi, w, df.TestFunction(V))
    jac = df.derivative(res, w, df.TrialFunction(V))
    # Force on the body along -z (the sphere's motion)
    nz = (x[1] - cz)/dist
    forceForm = twoPi*k*pen*(-nz)*r*ds(1)

    # Reaction on the bonded bottom (equilibrium check): the residual
    # without the bottom condition applied to a unit z field there
    unitZ = df.Function(V)
    df.DirichletBC(V.sub(0), df.Constant((0, 1)), bottom).apply(
        unitZ.vector())
    problem = df.NonlinearVariationalProblem(res, w, bcs, jac)
    solver = df.NonlinearVariationalSolver(problem)
    prm = solver.parameters["newton_solver"]
    prm["linear_solver"] = "umfpack"
    prm["absolute_tolerance"] = 1e-10*mu*H*H
    prm["relative_tolerance"] = 1e-10
    prm["maximum_iterations"] = 30
    prm["error_on_nonconvergence"] = True
    prm["report"] = False
    df.set_log_level(df.LogLevel.WARNING)

    t0 = time.time()
    done = 0.0
    out = []
    for target in args.depths:
        # Increments of at most args.step [um], halved when Newton fails
        its, cuts = 0, 0
        inc = args.step
        while done < target - 1e-12:
            trial = min(target, done + inc)
            saved = w.vector().get_local()
            depth.assign(trial)
            try:
                n, conv = solver.solve()
            except RuntimeError as e:
                print(f"depth {trial:.6g} um: {str(e).strip()[-400:]}",
                      file=sys.stderr, flush=True)
                w.vector().set_local(saved)
                w.vector().apply("insert")
                inc *= 0.5
                cuts += 1
                if inc < 1e-4*args.step:
                    raise
                continue
            its += n
            done = trial
        force = df.assemble(forceForm)
        reaction = unitZ.vector().inner(df.assemble(res))
        # Contact radius: largest current r of a penetrating top dof
        uu = w.sub(0, deepcopy=True)
        Vu = uu.function_space()
        xyDof = Vu.tabulate_dof_coordinates().reshape(-1, 2)
        uv = uu.vector().get_local()
        d0 = Vu.sub(0).dofmap().dofs()
        d1 = Vu.sub(1).dofmap().dofs()
        X = xyDof[d0]
        onTop = np.abs(X[:, 1] - H) < 1e-9
        xr = X[onTop, 0] + uv[d0][onTop]
        xz = X[onTop, 1] + uv[d1][onTop]
        g = np.hypot(xr, xz - (H + R - target)) - R
        aC = float(xr[g < 0].max()) if np.any(g < 0) else 0.0
        out.append(dict(level=args.level, n=args.n0*2**args.level,
                        m=args.m0*2**args.level, dofs=V.dim(),
                        K=args.K, mu=mu, penalty=args.penalty,
                        depth=target, force=force, reaction=reaction,
                        maxPenetration=float(-g.min()) if g.size else 0.0,
                        contactRadius=aC, newton=its, cuts=cuts,
                        seconds=time.time() - t0))
        print(json.dumps(out[-1]), flush=True)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--W", type=float, default=25.0, help="radius [um]")
    ap.add_argument("--H", type=float, default=7.9, help="thickness [um]")
    ap.add_argument("--R", type=float, default=22.5,
                    help="sphere radius [um]")
    ap.add_argument("--mu", type=float, default=13.33,
                    help="shear modulus [Pa]")
    ap.add_argument("--K", type=float, default=0.0,
                    help="bulk modulus [Pa], 0: incompressible")
    ap.add_argument("--penalty", type=float, required=True,
                    help="contact penalty k [Pa/um]")
    ap.add_argument("--level", type=int, default=0)
    ap.add_argument("--n0", type=int, default=20,
                    help="radial cells at level 0")
    ap.add_argument("--m0", type=int, default=8,
                    help="vertical cells at level 0")
    ap.add_argument("--rFine", type=float, default=9.0,
                    help="radius of the uniform cells [um]")
    ap.add_argument("--quadrature", type=int, default=8,
                    help="quadrature degree of the contact integral")
    ap.add_argument("--step", type=float, default=0.1,
                    help="largest depth increment [um]")
    ap.add_argument("--depths", type=float, nargs="+",
                    default=[0.1, 1.0, 1.5], help="depths [um], ascending")
    args = ap.parse_args()
    for name in ("W", "H", "R", "mu", "penalty", "step", "rFine"):
        if not getattr(args, name) > 0:
            sys.exit(f"fenicsLayer.py: --{name} must be > 0")
    if args.K < 0 or args.level < 0 or args.n0 < 1 or args.m0 < 1:
        sys.exit("fenicsLayer.py: --K >= 0, --level >= 0, --n0, --m0 >= 1")
    if any(b <= a for a, b in zip(args.depths, args.depths[1:])) \
            or args.depths[0] <= 0 or args.depths[-1] >= args.H:
        sys.exit("fenicsLayer.py: --depths ascending in (0, H) [um]")
    solve(args)


if __name__ == "__main__":
    main()
