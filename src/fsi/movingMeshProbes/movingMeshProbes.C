#include "movingMeshProbes.H"
#include "volPointInterpolation.H"
#include "addToRunTimeSelectionTable.H"

#include <Eigen/Dense>

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


bool Foam::movingMeshProbes::linearFit() const
{
    return fixedLocations_ && interpolationScheme_ == "cellLinearFit";
}


bool Foam::movingMeshProbes::cellPoint() const
{
    return fixedLocations_ && interpolationScheme_ == "cellPoint";
}


void Foam::movingMeshProbes::fitWeights
(
    List<labelList>& cells,
    List<scalarList>& weights
) const
{
    const labelListList& cellPoints = mesh_.cellPoints();
    const labelListList& pointCells = mesh_.pointCells();
    const vectorField& C = mesh_.cellCentres();

    // The fit's gradient in the solution directions only (a wedge's cell
    // centres all lie on its mid plane)
    const Vector<label>& solutionD = mesh_.solutionD();
    DynamicList<direction> dirs;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solutionD[d] == 1) dirs.append(d);
    }
    const label n = 1 + dirs.size();

    cells.setSize(size());
    weights.setSize(size());
    forAll(*this, probei)
    {
        cells[probei].clear();
        weights[probei].clear();
        const label celli = elementList_[probei];
        if (celli == -1)
        {
            continue;
        }

        // The cell and the cells that share a point with it
        DynamicList<label> st(32);
        st.append(celli);
        for (const label pointi : cellPoints[celli])
        {
            for (const label cellj : pointCells[pointi])
            {
                if (!st.found(cellj)) st.append(cellj);
            }
        }

        const point& x = operator[](probei);
        scalar h = 0;
        for (const label cellj : st) h += mag(C[cellj] - x);
        h /= st.size();

        // Normal equations in coordinates scaled by h: M m = e_0, then the
        // weight of cell i is w_i m.q_i with q_i = (1, (x_i - x_p)/h)
        Eigen::MatrixXd Q(st.size(), n);
        Eigen::VectorXd w(st.size());
        forAll(st, i)
        {
            const vector d = (C[st[i]] - x)/h;
            Q(i, 0) = 1;
            forAll(dirs, k) Q(i, k + 1) = d[dirs[k]];
            w(i) = 1/(magSqr(d) + 0.01);
        }
        const Eigen::MatrixXd M(Q.transpose()*w.asDiagonal()*Q);
        Eigen::VectorXd e0(Eigen::VectorXd::Zero(n));
        e0(0) = 1;
        const Eigen::VectorXd m(M.completeOrthogonalDecomposition().solve(e0));
        const Eigen::VectorXd lambda(w.cwiseProduct(Q*m));

        cells[probei].transfer(st);
        weights[probei].setSize(lambda.size());
        forAll(weights[probei], i) weights[probei][i] = lambda(i);
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
    if (!linearFit() && !cellPoint())
    {
        const bool written = probes::write();
        volPointInterpolation::Delete(mesh_);
        return written;
    }

    if (size() && prepare())
    {
        if
        (
            linearFit()
         && (
                surfaceScalarFields_.size() || surfaceVectorFields_.size()
             || surfaceSphericalTensorFields_.size()
             || surfaceSymmTensorFields_.size() || surfaceTensorFields_.size()
            )
        )
        {
            FatalErrorInFunction
                << name() << ": interpolationScheme cellLinearFit samples"
                << " vol fields only; fields " << fieldSelection_
                << " select surface fields" << exit(FatalError);
        }

        sampleAndWriteVol(scalarFields_);
        sampleAndWriteVol(vectorFields_);
        sampleAndWriteVol(sphericalTensorFields_);
        sampleAndWriteVol(symmTensorFields_);
        sampleAndWriteVol(tensorFields_);

        sampleAndWriteSurface(surfaceScalarFields_);
        sampleAndWriteSurface(surfaceVectorFields_);
        sampleAndWriteSurface(surfaceSphericalTensorFields_);
        sampleAndWriteSurface(surfaceSymmTensorFields_);
        sampleAndWriteSurface(surfaceTensorFields_);
    }

    // The whole-field interpolation where a tetrahedron's point values are
    // not localCellPoint's: its weights, a mesh object, would otherwise be
    // built again at every motion
    volPointInterpolation::Delete(mesh_);

    return true;
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
