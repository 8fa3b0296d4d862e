#include "HLL.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace riemannFluxes
{
    defineTypeNameAndDebug(HLL, 0);
    addToRunTimeSelectionTable(riemannFlux, HLL, mesh);
}
}
