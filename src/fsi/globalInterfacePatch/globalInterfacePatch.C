#include "globalInterfacePatch.H"
#include "Pstream.H"
#include "SubField.H"

#include <mpi.h>

#include <array>
#include <map>

Foam::globalInterfacePatch::globalInterfacePatch(const polyPatch& pp)
:
    name_(pp.name()),
    faceOffsets_(pp.size())
{
    if (!Pstream::parRun())
    {
        faces_ = pp.localFaces();
        points_ = pp.localPoints();
        faceCentres_ = pp.faceCentres();
        localToGlobal_ = identity(pp.nPoints());
        return;
    }

    // Every rank's patch on the master, in rank order
    List<pointField> allPoints(Pstream::nProcs());
    List<faceList> allFaces(Pstream::nProcs());
    allPoints[Pstream::myProcNo()] = pp.localPoints();
    allFaces[Pstream::myProcNo()] = pp.localFaces();
    Pstream::gatherList(allPoints);
    Pstream::gatherList(allFaces);
    faceOffsets_.gather(pointField(pp.faceCentres()), faceCentres_);

    // Merge the points that ranks share (equal coordinates: decomposePar
    // writes a shared point to each of its processors with the same bits)
    List<labelList> rankToGlobal(Pstream::nProcs());
    if (Pstream::master())
    {
        std::map<std::array<scalar, 3>, label> index;
        DynamicList<point> merged;
        forAll(allPoints, proci)
        {
            const pointField& p = allPoints[proci];
            labelList& map = rankToGlobal[proci];
            map.setSize(p.size());
            forAll(p, i)
            {
                const std::array<scalar, 3> key
                {{
                    p[i].x(), p[i].y(), p[i].z()
                }};
                const auto it = index.emplace(key, merged.size());
                if (it.second) merged.append(p[i]);
                map[i] = it.first->second;
            }
        }
        points_.transfer(merged);
        DynamicList<face> faces;
        forAll(allFaces, proci)
        {
            for (const face& f : allFaces[proci])
            {
                face g(f.size());
                forAll(f, k) g[k] = rankToGlobal[proci][f[k]];
                faces.append(g);
            }
        }
        faces_.transfer(faces);
    }
    Pstream::scatter(points_);
    Pstream::scatter(faces_);
    Pstream::scatter(faceCentres_);
    // (scatterList would not send a rank its own entry)
    Pstream::scatter(rankToGlobal);
    localToGlobal_ = rankToGlobal[Pstream::myProcNo()];
}


Foam::tmp<Foam::scalarField> Foam::globalInterfacePatch::packedFaceValues
(
    const UList<scalar>& local,
    const label width
) const
{
    if (local.size() != width*faceOffsets_.localSize())
    {
        FatalErrorInFunction
            << "patch " << name_ << ": " << local.size() << " values for "
            << faceOffsets_.localSize() << " faces of " << width
            << " values each" << exit(FatalError);
    }
    if (!Pstream::parRun())
    {
        return tmp<scalarField>(new scalarField(local));
    }
    tmp<scalarField> tall(new scalarField(width*faceOffsets_.size()));
    List<int> counts(Pstream::nProcs());
    List<int> starts(Pstream::nProcs());
    forAll(counts, proci)
    {
        counts[proci] = int(width*faceOffsets_.localSize(proci));
        starts[proci] = int(width*faceOffsets_.offset(proci));
    }
    // OpenFOAM's world communicator is MPI_COMM_WORLD
    MPI_Allgatherv
    (
        const_cast<scalar*>(local.cdata()), int(local.size()), MPI_DOUBLE,
        tall.ref().data(), counts.cdata(), starts.cdata(), MPI_DOUBLE,
        MPI_COMM_WORLD
    );
    return tall;
}
