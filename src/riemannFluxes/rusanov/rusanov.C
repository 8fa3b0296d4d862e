#include "rusanov.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace riemannFluxes
{
    defineTypeNameAndDebug(rusanov, 0);
    addToRunTimeSelectionTable(riemannFlux, rusanov, mesh);
}
}
