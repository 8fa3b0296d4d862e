#include "HLLC.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace riemannFluxes
{
    defineTypeNameAndDebug(HLLC, 0);
    addToRunTimeSelectionTable(riemannFlux, HLLC, mesh);
}
}
