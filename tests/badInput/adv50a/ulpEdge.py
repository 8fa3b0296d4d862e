#!/usr/bin/python3
"""ulpEdge.py LAW RHO: the restart-state check's sound-speed edge (conservativeFluid::checkRestartState, refused unless
c < physicalBounds::soundSpeedMax = 1e5 m/s) in doubles, for a cell at rest of density RHO [kg/m^3]: prints two values of
rhoE [J/m^3], 'below' (the largest whose c < 1e5 m/s: accepted) and 'at' (the next double: c >= 1e5 m/s, refused), with
the c each gives. The law's arithmetic as the C++ writes it (src/eos/IdealGas.H c2 = gamma*(gamma - 1)*e;
src/eos/MieGruneisen.H c2 = dpdrho + p*G0rho0/(rho*rho), pH, pCold, dpColdDEta), e = rhoE/rho - 0.5*|U|^2 with U = 0.
LAW: idealGas (gamma 1.4: sodIdealGas) or mieGruneisen (rho0 1000, C0 1450, s 1.99, Gamma0 0.1: the preview's water).
Python's float is the C double and math.sqrt is correctly rounded as std::sqrt is, so the edge is the C++'s own."""
import math, sys
law, rho = sys.argv[1], float(sys.argv[2])
if law == 'idealGas':
    g = 1.4
    def c(rhoE):
        e = rhoE/rho - 0.5*0.0*0.0
        return math.sqrt(g*(g - 1)*e)
else:
    rho0, C0, s, G0 = 1000.0, 1450.0, 1.99, 0.1
    rho0C02, G0rho0 = rho0*C0*C0, G0*rho0
    def pH(eta): d = 1.0 - s*eta; return rho0C02*eta/(d*d)
    def dpHdEta(eta): d = 1.0 - s*eta; return rho0C02*(1.0 + s*eta)/(d*d*d)
    def pCold(eta): return pH(eta)*(1.0 - 0.5*G0*eta)
    def dpColdDEta(eta): return dpHdEta(eta)*(1.0 - 0.5*G0*eta) - 0.5*G0*pH(eta)
    def c(rhoE):
        e = rhoE/rho - 0.5*0.0*0.0; eta = 1.0 - rho0/rho
        p = pCold(eta) + G0rho0*e; dpdrho = dpColdDEta(eta)*rho0/(rho*rho)
        return math.sqrt(dpdrho + p*G0rho0/(rho*rho))
lo, hi = 0.0, 1e300          # c(lo) < 1e5 <= c(hi); bisect on the doubles
while math.nextafter(lo, math.inf) < hi:
    mid = lo + (hi - lo)/2
    if mid <= lo or mid >= hi: mid = math.nextafter(lo, math.inf)
    if c(mid) < 1e5: lo = mid
    else: hi = mid
print('below %r c=%r' % (lo, c(lo)))
print('at %r c=%r' % (hi, c(hi)))
