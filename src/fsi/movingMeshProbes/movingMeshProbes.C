#include "movingMeshProbes.H"
#include "volPointInterpolation.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(movingMeshProbes, 0);
    addToRunTimeSelectionTable(functionObject, movingMeshProbes, dictionary);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::movingMeshProbes::cellsHoldProbes() const
{
    forAll(*this, probei)
    {
        const label celli = elementList_[probei];
        if
        (
            celli != -1
         && !mesh_.pointInCell(operator[](probei), celli, polyMesh::CELL_TETS)
        )
        {
            return false;
        }
    }
    return true;
}


void Foam::movingMeshProbes::updateFaces()
{
    forAll(*this, probei)
    {
        const label celli = elementList_[probei];
        if (celli == -1)
        {
            continue;
        }
        const point& centre = mesh_.cellCentres()[celli];
        scalar minDistance = GREAT;
        for (const label facei : mesh_.cells()[celli])
        {
            const scalar distance = mag(mesh_.faceCentres()[facei] - centre);
            if (distance < minDistance)
            {
                minDistance = distance;
                faceList_[probei] = facei;
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::movingMeshProbes::movingMeshProbes
(
    const word& name,
    const Time& runTime,
    const dictionary& dict,
    const bool loadFromFiles,
    const bool readFields
)
:
    probes(name, runTime, dict, loadFromFiles, readFields)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::movingMeshProbes::write()
{
    const bool written = probes::write();
    volPointInterpolation::Delete(mesh_);
    return written;
}


void Foam::movingMeshProbes::movePoints(const polyMesh& mesh)
{
    if (!fixedLocations_ || &mesh != &mesh_)
    {
        probes::movePoints(mesh);
        return;
    }

    // One decision for all ranks: findElements reduces over them
    if (returnReduce(cellsHoldProbes(), andOp<bool>()))
    {
        updateFaces();
    }
    else
    {
        findElements(mesh_);
    }
}


// ************************************************************************* //
