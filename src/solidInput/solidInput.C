#include "solidInput.H"
#include "solidEntries.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "Tuple2.H"
#include "labelVector.H"
#include "vector.H"
#include "vector2D.H"

#include "GmshReader.H"
#include "SolidError.H"
#include "keywordCheck.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::solidInput::solidInput
(
    const dictionary& solidProperties,
    const fileName& caseDir,
    const wordList& solverEntries
)
:
    dict_(solidProperties),
    caseDir_(caseDir)
{
    wordList valid{"mesh", "fixed", "materials"};
    valid.append(solverEntries);
    foamTools::checkKeywords(dict_, valid);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

solid::Mesh Foam::solidInput::mesh() const
{
    const dictionary& dict = dict_.subDict("mesh");
    const word type(dict.get<word>("type"));
    if (type == "box" || type == "rectangle")
    {
        foamTools::checkKeywords(dict, {"type", "cells", "min", "max"});
    }
    else if (type == "gmsh")
    {
        foamTools::checkKeywords(dict, {"type", "file", "scale"});
    }
    try
    {
        if (type == "box")
        {
            const labelVector n(dict.get<labelVector>("cells"));
            const vector lo(dict.get<vector>("min"));
            const vector hi(dict.get<vector>("max"));
            return solid::Mesh::box
            (
                n.x(), n.y(), n.z(),
                solid::Vec3(lo.x(), lo.y(), lo.z()),
                solid::Vec3(hi.x(), hi.y(), hi.z())
            );
        }
        if (type == "rectangle")
        {
            const Vector2D<label> n(dict.get<Vector2D<label>>("cells"));
            const vector2D lo(dict.get<vector2D>("min"));
            const vector2D hi(dict.get<vector2D>("max"));
            return solid::Mesh::rectangle
            (
                n.x(), n.y(), lo.x(), hi.x(), lo.y(), hi.y()
            );
        }
        if (type == "gmsh")
        {
            fileName file(dict.get<fileName>("file"));
            file.expand();
            if (!file.isAbsolute()) file = caseDir_/file;
            if (!isFile(file))
            {
                FatalIOErrorInFunction(dict)
                    << "Cannot find " << file << " (entry 'file'; run "
                    << "cellMesh first)" << exit(FatalIOError);
            }
            return solid::readGmsh
            (
                file,
                foamTools::readInRangeOrDefault<scalar>
                (
                    dict, "scale", "", 0, foamTools::noUpperBound<scalar>(),
                    false, 1
                )
            );
        }
    }
    catch (const solid::SolidError& err)
    {
        FatalIOErrorInFunction(dict)
            << "solid mesh " << type << ": " << err.what()
            << exit(FatalIOError);
    }
    FatalIOErrorInFunction(dict)
        << "Unknown solid mesh type " << type
        << "; valid types: (box rectangle gmsh)" << exit(FatalIOError);
    return solid::Mesh();
}


std::vector<solid::MaterialParameters> Foam::solidInput::materials
(
    const solid::Mesh& mesh
) const
{
    const dictionary& mats = dict_.subDict("materials");
    const wordList regions(mesh.regionNames.begin(), mesh.regionNames.end());

    // The paper's parameter sets are data files now: a case of an earlier
    // version names one with parameterSet
    if (mats.found("parameterSet", keyType::LITERAL))
    {
        FatalIOErrorInFunction(mats)
            << "entry 'parameterSet' is no longer read: the paper's "
            << "parameter sets are dictionaries, included in 'materials' as"
            << nl << "    #include \"$PROJECT_DIR/etc/caseDicts/"
            << "cellMaterials/<set>\"" << nl << "with <set> one of table, "
            << "text, textFactor4, instantaneous (docs/userGuide/"
            << "solidProperties.md)" << exit(FatalIOError);
    }

    // Every entry must name a region of the mesh: a misspelt region would
    // otherwise be ignored silently
    foamTools::checkKeywords(mats, regions);

    std::vector<solid::MaterialParameters> result;
    for (const word& region : regions)
    {
        if (!mats.isDict(region))
        {
            FatalIOErrorInFunction(mats)
                << "no material for region '" << region << "': give a "
                << "sub-dictionary '" << region << "' (the paper's sets: "
                << "#include \"$PROJECT_DIR/etc/caseDicts/cellMaterials/"
                << "<set>\")" << exit(FatalIOError);
        }
        const dictionary& d = mats.subDict(region);
        // The entries themselves: solid::MaterialParameters::fromEntries
        foamTools::checkDuplicates(d);
        solid::MaterialParameters p;
        try
        {
            p = solid::MaterialParameters::fromEntries
            (
                region, solidEntries(d, "material '" + region + "'")
            );
        }
        catch (const solid::SolidError& err)
        {
            FatalIOErrorInFunction(d) << err.what() << exit(FatalIOError);
        }
        Info<< "    " << region << ": C10 " << p.C10 << " Pa, d0 " << p.d0
            << " 1/Pa";
        for (const auto& b : p.branches)
        {
            Info<< ", mu " << b.mu << " Pa tau " << b.tau << " s";
        }
        Info<< nl;
        result.push_back(p);
    }
    Info<< endl;
    return result;
}


std::vector<solid::MaterialParameters> Foam::solidInput::setup
(
    solid::Model& model
) const
{
    const std::vector<solid::MaterialParameters> mats =
        materials(model.mesh());
    for (const solid::MaterialParameters& p : mats)
    {
        model.setMaterial(p.name, solid::Material::create(p));
    }
    for (const auto& f : dict_.get<List<Tuple2<word, label>>>("fixed"))
    {
        try
        {
            model.fix(f.first(), f.second());
        }
        catch (const solid::SolidError& err)
        {
            FatalIOErrorInFunction(dict_)
                << "entry 'fixed': " << err.what() << exit(FatalIOError);
        }
    }
    return mats;
}


Foam::foamTools::inputRecord::digestMap Foam::solidInput::digests
(
    const solid::Mesh& mesh
) const
{
    using foamTools::inputRecord;
    const std::string file("constant/solidProperties, entry ");
    inputRecord::digestMap record;
    const dictionary& meshDict = dict_.subDict("mesh");
    record[file + "'mesh'"] = inputRecord::digest(meshDict);
    if (meshDict.get<word>("type") == "gmsh")
    {
        fileName name(meshDict.get<fileName>("file"));
        name.expand();
        const fileName path(name.isAbsolute() ? name : caseDir_/name);
        record[name] = inputRecord::sha1(inputRecord::bytes(path));
    }
    dictionary fixed;
    fixed.add(dict_.lookupEntry("fixed", keyType::LITERAL));
    record[file + "'fixed'"] = inputRecord::digest(fixed);
    const dictionary& mats = dict_.subDict("materials");
    for (const std::string& region : mesh.regionNames)
    {
        record[file + "'materials', region '" + region + "'"] =
            inputRecord::digest(mats.subDict(region));
    }
    return record;
}


void Foam::solidInput::writeMaterials
(
    const std::vector<solid::MaterialParameters>& materials,
    const fileName& file
)
{
    OFstream os(file);
    os.precision(17);
    os  << "# region  rho0 [kg/m^3]  C10 [Pa]  d0 [1/Pa]  then for each "
        << "Maxwell branch N = 1, 2, ...: muN [Pa]  tauN [s]" << nl;
    for (const solid::MaterialParameters& p : materials)
    {
        os  << word(p.name) << ' ' << p.rho0 << ' ' << p.C10 << ' ' << p.d0;
        for (const auto& b : p.branches)
        {
            os  << ' ' << b.mu << ' ' << b.tau;
        }
        os  << nl;
    }
}


// ************************************************************************* //
