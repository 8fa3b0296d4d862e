#include "solidInput.H"
#include "solidEntries.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "Tuple2.H"
#include "DynamicList.H"
#include "labelVector.H"
#include "vector.H"
#include "vector2D.H"

#include "GmshReader.H"
#include "fileKind.H"
#include "SolidError.H"
#include "StringEntries.H"
#include "keywordCheck.H"
#include "inputChecks.H"
#include "subDict.H"

namespace
{

// The nodes of a region's elements (empty: no region of that name)
std::vector<char> regionNodes
(
    const solid::Mesh& mesh,
    const std::string& name
)
{
    std::vector<char> in;
    for (std::size_t r = 0; r < mesh.regionNames.size(); ++r)
    {
        if (mesh.regionNames[r] != name)
        {
            continue;
        }
        in.assign(mesh.nNodes(), 0);
        const int nen = mesh.nen();
        for (int e = 0; e < mesh.nElements(); ++e)
        {
            if (mesh.region[e] == int(r))
            {
                for (int a = 0; a < nen; ++a)
                {
                    in[mesh.element(e)[a]] = 1;
                }
            }
        }
    }
    return in;
}

// The valid range of entry key of a material, "(0, 1e+13) Pa" ("" for no
// entry of a material), by the reader's own checks: a valid material with
// key not a number, read by solid::MaterialParameters::fromEntries, which
// names the range of such an entry (the law's entries of a mieGruneisen
// material, d0 of a quadratic one; a branch numbered as key, with the
// branches before it)
std::string materialRange(const std::string& key)
{
    std::map<std::string, std::string> e
    {
        {"rho0", "1000"}, {"C10", "1"}, {"volumetric", "mieGruneisen"},
        {"C0", "1450"}, {"s", "1.99"}, {"Gamma0", "0.1"}, {"Cv", "4184"},
        {"T0", "293.15"}
    };
    if (key == "d0")
    {
        e["volumetric"] = "quadratic";
    }
    const bool scalar =
        e.count(key) || key == "d0" || key == "b1" || key == "b2";
    const std::string::size_type digits = key.find_first_of("0123456789");
    if (!scalar && digits != std::string::npos && digits > 0)
    {
        const std::string prefix(key.substr(0, digits));
        const int n = std::atoi(key.c_str() + digits);
        if
        (
            (prefix != "mu" && prefix != "tau" && prefix != "eta")
         || key.find_first_not_of("0123456789", digits) != std::string::npos
         || n < 1 || n > 100
        )
        {
            return std::string();
        }
        for (int i = 1; i <= n; ++i)
        {
            e["mu" + std::to_string(i)] = "1";
            e[(i == n && prefix == "eta" ? "eta" : "tau")
              + std::to_string(i)] = "1";
        }
    }
    else if (!scalar)
    {
        return std::string();
    }
    e[key] = "nan";
    try
    {
        solid::MaterialParameters::fromEntries
        (
            "range", solid::StringEntries("range", e)
        );
    }
    catch (const solid::SolidError& err)
    {
        const std::string what(err.what());
        const std::string tag("; valid range ");
        const std::string::size_type at = what.find(tag);
        if (at != std::string::npos)
        {
            return what.substr(at + tag.size());
        }
    }
    return std::string();
}

// The scan of the numbers' range of an entry of constant/solidProperties:
// a material's (materials/<region>/<key>)
std::string solidPropertiesRange
(
    const std::string& dictName,
    const std::vector<std::string>& scope,
    const std::string& key
)
{
    if
    (
        dictName != "solidProperties" || scope.size() != 2
     || scope[0] != "materials"
    )
    {
        return std::string();
    }
    return materialRange(key);
}

const bool solidPropertiesRangeAdded =
    Foam::foamTools::addScanRange(solidPropertiesRange);

} // End anonymous namespace


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
    foamTools::requireValue
    (
        dict_, "fixed", "a list of (node set, component) pairs, e.g."
        " ((xmax 0) (ymin 1))"
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

solid::Mesh Foam::solidInput::mesh() const
{
    const dictionary& dict = foamTools::subDict(dict_, "mesh");
    const word type(dict.get<word>("type"));
    if (type == "box" || type == "rectangle")
    {
        foamTools::checkKeywords(dict, {"type", "cells", "min", "max"});
    }
    else if (type == "gmsh")
    {
        foamTools::checkKeywords(dict, {"type", "file", "scale"});
    }
    // The elements checked here, where a failure names this dictionary
    // (solid::Model checks them again and threw past the solvers, adv32
    // f15: std::terminate)
    const auto checked = [](solid::Mesh mesh)
    {
        mesh.check();
        return mesh;
    };
    try
    {
        if (type == "box")
        {
            const labelVector n(dict.get<labelVector>("cells"));
            const vector lo(dict.get<vector>("min"));
            const vector hi(dict.get<vector>("max"));
            return checked
            (
                solid::Mesh::box
                (
                    n.x(), n.y(), n.z(),
                    solid::Vec3(lo.x(), lo.y(), lo.z()),
                    solid::Vec3(hi.x(), hi.y(), hi.z())
                )
            );
        }
        if (type == "rectangle")
        {
            const Vector2D<label> n(dict.get<Vector2D<label>>("cells"));
            const vector2D lo(dict.get<vector2D>("min"));
            const vector2D hi(dict.get<vector2D>("max"));
            return checked
            (
                solid::Mesh::rectangle
                (
                    n.x(), n.y(), lo.x(), hi.x(), lo.y(), hi.y()
                )
            );
        }
        if (type == "gmsh")
        {
            fileName file(dict.get<fileName>("file"));
            file.expand();
            if (!file.isAbsolute()) file = caseDir_/file;
            if (!isFile(file))
            {
                // a directory (adv32 z04: "Cannot find"), a FIFO, ...
                // named as such
                const std::string kind(foamTools::notARegularFile(file));
                FatalIOErrorInFunction(dict)
                    << "entry 'file' = " << file << ": "
                    << (kind.empty() ? std::string("no such file (run "
                        "cellMesh first)") : kind + ", not a gmsh mesh file")
                        .c_str()
                    << exit(FatalIOError);
            }
            // The file's unit in metres, from nm (1e-9) to km (1e3): a
            // scale without an upper bound (was (0, inf)) overflowed the
            // reader's Jacobians before the size check below could refuse
            // it, 'scale 1e300' a floating point exception (adv38 x58,
            // x74); within this range a file's coordinates would have to
            // pass 1e148 for that
            const scalar scale = foamTools::readInRangeOrDefault<scalar>
            (
                dict, "scale", "", 1e-9, 1e3, true, 1
            );
            solid::Mesh mesh(checked(solid::readGmsh(file, scale)));
            // A cell: its size in metres after scaling lies in cellMesh's
            // range of cellDiameter, (1e-7, 1e-3] m (a mesh in micrometres
            // or scaled by 1e6 failed later in the solver, naming no
            // input; issue 19)
            solid::Vec3 lo(mesh.X[0]), hi(mesh.X[0]);
            for (const solid::Vec3& x : mesh.X)
            {
                lo = lo.cwiseMin(x);
                hi = hi.cwiseMax(x);
            }
            const scalar size = (hi - lo).maxCoeff();
            if (!(size > 1e-7 && size <= 1e-3))
            {
                FatalIOErrorInFunction(dict)
                    << "the solid mesh " << file << " scaled by entry"
                    << " 'scale' = " << scale << " is " << size << " m"
                    << " across (from (" << lo(0) << " " << lo(1) << " "
                    << lo(2) << ") m to (" << hi(0) << " " << hi(1) << " "
                    << hi(2) << ") m): a cell is between 1e-07 and"
                    << " 0.001 m (valid range (1e-07, 0.001] m, cellMesh's"
                    << " cellDiameter); check the mesh's units and 'scale'"
                    << " (metres after scaling)" << exit(FatalIOError);
            }
            return mesh;
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
    const dictionary& mats = foamTools::subDict(dict_, "materials");
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

    // A mesh without names for its regions (physical groups without
    // $PhysicalNames: read as region<tag>) while the materials name
    // regions: say so, not "unknown entry 'nucleus'" (issue 19)
    {
        DynamicList<word> unnamed;
        for (const word& region : regions)
        {
            if
            (
                region.size() > 6 && region.compare(0, 6, "region") == 0
             && region.find_first_not_of("0123456789", 6) == std::string::npos
             && !mats.found(region, keyType::LITERAL)
            )
            {
                unnamed.append(region);
            }
        }
        DynamicList<word> named;
        for (const entry& e : mats)
        {
            if (e.isDict() && !regions.found(e.keyword()))
            {
                named.append(e.keyword());
            }
        }
        if (unnamed.size() && named.size())
        {
            const dictionary& meshDict = foamTools::subDict(dict_, "mesh");
            FatalIOErrorInFunction(mats)
                << "the solid mesh";
            if (meshDict.found("file"))
            {
                FatalIOError
                    << " '" << meshDict.get<fileName>("file").c_str() << "'";
            }
            FatalIOError
                << " gives no name to its region"
                << (unnamed.size() == 1 ? "" : "s") << " "
                << wordList(unnamed) << " (physical groups without a name:"
                << " no $PhysicalNames section?), while 'materials' names the"
                << " regions " << wordList(named) << ": name the physical"
                << " groups in the mesh (Physical Surface(\"nucleus\") = ..."
                << " in the .geo, or cellMesh), or give the materials"
                << " under the names read" << exit(FatalIOError);
        }
    }

    // Every entry must name a region of the mesh: a misspelt region would
    // otherwise be ignored silently
    foamTools::checkKeywords(mats, regions);

    // The cell's regions by name must fit its geometry: the nucleus lies
    // inside the cytoplasm, the membrane outside it and on the cell's
    // outer surface. A mesh whose names of the nucleus and the cytoplasm
    // were swapped ran to its end with each region's material on the
    // other (adv46b d40; issue 19's "swapped physical-group names")
    {
        const std::vector<char> nucleus(regionNodes(mesh, "nucleus"));
        const std::vector<char> membrane(regionNodes(mesh, "membrane"));
        const std::vector<char> cytoplasm(regionNodes(mesh, "cytoplasm"));
        const std::vector<char>& outer =
            membrane.size() ? membrane : cytoplasm;
        const char* outerName = membrane.size() ? "membrane" : "cytoplasm";
        std::string why;
        if (nucleus.size() && membrane.size())
        {
            for (int n = 0; n < mesh.nNodes() && why.empty(); ++n)
            {
                if (nucleus[n] && membrane[n])
                {
                    why = "the region 'nucleus' touches the region"
                        " 'membrane' (they share nodes; the cytoplasm lies"
                        " between them)";
                }
            }
        }
        const auto surface = mesh.faceSets.find("outerSurface");
        if (why.empty() && outer.size() && surface != mesh.faceSets.end())
        {
            for (const std::vector<int>& f : surface->second)
            {
                bool all = true;
                for (const int n : f)
                {
                    all = all && outer[n];
                }
                if (!all)
                {
                    why = std::string("a face of 'outerSurface' is not on")
                        + " the region '" + outerName + "' (the cell's"
                        + " outermost region)";
                    break;
                }
            }
        }
        if (!why.empty())
        {
            const dictionary& meshDict = foamTools::subDict(dict_, "mesh");
            FatalIOErrorInFunction(mats)
                << "the regions of the solid mesh";
            if (meshDict.found("file"))
            {
                FatalIOError
                    << " '" << meshDict.get<fileName>("file").c_str() << "'";
            }
            FatalIOError
                << " do not fit their names: " << why.c_str()
                << ". Are the names of the physical groups swapped"
                << " ($PhysicalNames: " << wordList(regions) << ")? Each"
                << " region would get the other's material: nothing was"
                << " run. Name the groups as the geometry has them"
                << exit(FatalIOError);
        }
    }

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
        const dictionary& d = foamTools::subDict(mats, region);
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
            // The file and line of the entry named when it is not the
            // dictionary's own (a set of materials #include'd: adv48a h08
            // named constant/solidProperties only)
            const std::string what(err.what());
            const std::string::size_type at = what.find("entry '");
            const std::string::size_type end =
                at == std::string::npos ? at : what.find('\'', at + 7);
            const std::string given
            (
                end == std::string::npos
              ? std::string()
              : foamTools::givenIn(d, word(what.substr(at + 7, end - at - 7)))
            );
            FatalIOErrorInFunction(d)
                << what.c_str() << given.c_str() << exit(FatalIOError);
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
    const label dim = model.mesh().dim();
    const List<Tuple2<word, label>> fixedRows
    (
        dict_.get<List<Tuple2<word, label>>>("fixed")
    );
    // Nothing held: the load carries the cell away as a rigid body (and
    // through the substrate it rests on); adv37 w97 ran to its end
    if (fixedRows.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "entry 'fixed' is empty: nothing holds the cell, so the load"
            << " moves it as a rigid body (through the substrate it rests"
            << " on). Hold it where it is attached, e.g. ((fixedBottom 0)"
            << " (fixedBottom 1)" << (dim == 2 ? " (axis 0)" : "")
            << "); the node sets of the mesh: "
            << nodeSetNames(model.mesh()).c_str() << exit(FatalIOError);
    }
    for (const auto& f : fixedRows)
    {
        // the component by the row and the mesh's valid ones (adv33
        // sp02: "Dirichlet condition on node 93 component 2 is out of
        // range")
        if (f.second() < 0 || f.second() >= dim)
        {
            FatalIOErrorInFunction(dict_)
                << "entry 'fixed': row (" << f.first() << " " << f.second()
                << "): component " << f.second() << " is not one of the "
                << (dim == 2 ? "r-z" : "3D") << " mesh's components, valid: "
                << (dim == 2 ? "0 (r) or 1 (z)" : "0 (x), 1 (y) or 2 (z)")
                << exit(FatalIOError);
        }
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
    if (model.mesh().axisymmetric())
    {
        checkAxis(model.mesh(), fixedRows);
    }
    return mats;
}


std::string Foam::solidInput::nodeSetNames(const solid::Mesh& mesh)
{
    std::string names;
    for (const auto& s : mesh.nodeSets)
    {
        names += (names.empty() ? "" : ", ") + s.first;
    }
    return names.empty() ? std::string("(none)") : names;
}


void Foam::solidInput::checkAxis
(
    const solid::Mesh& mesh,
    const List<Tuple2<word, label>>& fixed
) const
{
    // Nodes with u_r fixed (component 0 of a listed set)
    std::vector<bool> held(mesh.nNodes(), false);
    for (const auto& f : fixed)
    {
        const auto it = mesh.nodeSets.find(f.first());
        if (f.second() == 0 && it != mesh.nodeSets.end())
        {
            for (const int n : it->second)
            {
                held[n] = true;
            }
        }
    }
    // On the axis: r within 1e-9 of the mesh's radial extent of 0
    double rMax = 0;
    for (const solid::Vec3& x : mesh.X)
    {
        rMax = std::max(rMax, x[0]);
    }
    label free = 0;
    label first = -1;
    for (label n = 0; n < mesh.nNodes(); ++n)
    {
        if (mesh.X[n][0] <= 1e-9*rMax && !held[n])
        {
            if (first < 0)
            {
                first = n;
            }
            ++free;
        }
    }
    if (free)
    {
        // The node sets that lie on the axis: the ones to name
        std::string onAxis;
        for (const auto& s : mesh.nodeSets)
        {
            bool all = !s.second.empty();
            for (const int n : s.second)
            {
                all = all && mesh.X[n][0] <= 1e-9*rMax;
            }
            if (all)
            {
                onAxis += (onAxis.empty() ? "" : ", ") + s.first;
            }
        }
        FatalIOErrorInFunction(dict_)
            << "entry 'fixed' leaves u_r free on " << free << " node(s) on"
            << " the axis r = 0 of the r-z mesh (the first: node " << first
            << " at z = " << mesh.X[first][1] << " m): a solid of revolution"
            << " has u_r = 0 there (free, the results are no model of one)."
            << " Add the row (<set> 0) for the"
            << " node set on the axis"
            << (onAxis.empty() ? std::string() : " (here: " + onAxis + ")")
               .c_str()
            << ", e.g. (axis 0)" << exit(FatalIOError);
    }
}


void Foam::solidInput::checkHeld(const label comp, const word& axis) const
{
    const List<Tuple2<word, label>> fixed
    (
        dict_.get<List<Tuple2<word, label>>>("fixed")
    );
    for (const auto& f : fixed)
    {
        if (f.second() == comp)
        {
            return;
        }
    }
    FatalIOErrorInFunction(dict_)
        << "entry 'fixed' holds " << fixed.size() << " rows and none fixes"
        << " component " << comp << " (" << axis.c_str() << ", the"
        << " indentation axis): a static indentation needs the cell held"
        << " along it, else the sphere pushes it away as a rigid body and"
        << " no step converges. Give a row (<node set> " << comp << "), e.g."
        << " (fixedBottom " << comp << ")" << exit(FatalIOError);
}


Foam::foamTools::inputRecord::digestMap Foam::solidInput::digests
(
    const solid::Mesh& mesh
) const
{
    using foamTools::inputRecord;
    const std::string file("constant/solidProperties, entry ");
    inputRecord::digestMap record;
    const dictionary& meshDict = foamTools::subDict(dict_, "mesh");
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
    const dictionary& mats = foamTools::subDict(dict_, "materials");
    for (const std::string& region : mesh.regionNames)
    {
        record[file + "'materials', region '" + region + "'"] =
            inputRecord::digest(foamTools::subDict(mats, region));
    }
    // Since fix19d (byEntryKey): the rows of 'fixed' as a set (the same
    // constraints in another order are the same input: adv46b d10 (a))
    // and each material entry on its own, named by its path (adv46b d02
    // (b): "region 'nucleus' (changed)" named neither mu1 nor the file
    // it was read from). The keys above stay for the checkpoints of
    // earlier builds (sameVersion)
    record[byEntryKey()] = inputRecord::sha1(byEntryKey());
    std::set<std::string> rows;
    for
    (
        const Tuple2<word, label>& row
      : dict_.get<List<Tuple2<word, label>>>("fixed")
    )
    {
        rows.insert(row.first() + " " + std::to_string(row.second()));
    }
    std::string rowsText;
    for (const std::string& row : rows)
    {
        rowsText += row + "\n";
    }
    record[fixedSetKey()] = inputRecord::sha1(rowsText);
    for (const std::string& region : mesh.regionNames)
    {
        for
        (
            const auto& leaf
          : inputRecord::leaves
            (
                foamTools::subDict(mats, region), "materials/" + region + "/"
            )
        )
        {
            record[file + "'" + leaf.first + "'"] = leaf.second;
        }
    }
    return record;
}


const char* Foam::solidInput::byEntryKey()
{
    return "constant/solidProperties (fixed as a set, the materials by"
        " entry)";
}


std::string Foam::solidInput::fixedSetKey()
{
    return "constant/solidProperties, entry 'fixed' (its rows as a set)";
}


void Foam::solidInput::sameVersion
(
    foamTools::inputRecord::digestMap& now,
    foamTools::inputRecord::digestMap& was
)
{
    const std::string file("constant/solidProperties, entry ");
    const std::string region(file + "'materials', region '");
    const std::string material(file + "'materials/");
    const bool byEntry = was.count(byEntryKey());
    const auto legacy = [&](const std::string& k)
    {
        return k == file + "'fixed'" || k.compare(0, region.size(), region)
         == 0;
    };
    const auto since = [&](const std::string& k)
    {
        return k == byEntryKey() || k == fixedSetKey()
         || k.compare(0, material.size(), material) == 0;
    };
    for (foamTools::inputRecord::digestMap* m : {&now, &was})
    {
        for (auto it = m->begin(); it != m->end();)
        {
            const bool drop = byEntry ? legacy(it->first) : since(it->first);
            it = drop ? m->erase(it) : std::next(it);
        }
    }
}


std::map<std::string, std::string> Foam::solidInput::sources() const
{
    std::map<std::string, std::string> found;
    const std::string prefix(caseDir_ + "/");
    for
    (
        const auto& item
      : foamTools::inputRecord::entrySources
        (
            caseDir_/"constant"/"solidProperties"
        )
    )
    {
        std::string shown(item.second);
        if (shown.compare(0, prefix.size(), prefix) == 0)
        {
            shown.erase(0, prefix.size());
        }
        found["constant/solidProperties, entry '" + item.first + "'"] =
            shown;
    }
    return found;
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
