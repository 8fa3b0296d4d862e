#include "ResultWriter.H"
#include "AtomicFile.H"
#include "Hdf5File.H"
#include "ModelSnapshot.H"
#include "SolidError.H"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <random>

namespace
{

std::vector<double> nodeVectors(const solid::Model& m, const Eigen::VectorXd& x)
{
    const int dim = m.mesh().dim();
    std::vector<double> out(3*m.mesh().nNodes(), 0.0);
    for (int n = 0; n < m.mesh().nNodes(); ++n)
        for (int i = 0; i < dim; ++i) out[3*n + i] = x(n*dim + i);
    return out;
}

} // namespace


solid::ResultWriter::ResultWriter
(
    const std::string& base,
    const Model& model,
    bool append,
    const std::string& runId
)
:
    base_(base),
    runId_(runId)
{
    if (append)
    {
        checkContinued(h5File(), runId_);
        // The .xmf is derived from the .h5: a run killed between the two
        // renames of write() left it one step behind
        steps_ = steps(h5File());
        writeXdmf(model);
        return;
    }
    const std::string tmp = temporaryName(h5File());
    {
        Hdf5File f(tmp, Hdf5File::Mode::create);
        {
            Hdf5Group mesh(f, "mesh", true);
            const Mesh& m = model.mesh();
            std::vector<double> X(3*m.nNodes());
            for (int n = 0; n < m.nNodes(); ++n)
                for (int i = 0; i < 3; ++i) X[3*n + i] = m.X[n](i);
            mesh.write("coordinates", X.data(), m.nNodes(), 3);
            mesh.write("connectivity", m.conn.data(), m.nElements(),
                       m.nen());
            mesh.write("region", m.region.data(), m.nElements());
            Hdf5Group s(f, "steps", true);
        }
        if (!runId_.empty()) f.writeText("runId", runId_);
        f.close();
    }
    commitFile(tmp, h5File());
    // The .xmf of the new file, with no steps: an earlier .xmf would list
    // steps that are gone (a new run whose first step fails left it)
    writeXdmf(model);
}


int solid::ResultWriter::write(Model& model)
{
    const Mesh& m = model.mesh();
    const int ne = m.nElements();
    std::vector<double> sigma(9*ne), p(ne), vm(ne), J(ne), dT(ne);
    for (int e = 0; e < ne; ++e)
    {
        const ElementOutput o = model.evaluateElement(e, 0);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) sigma[9*e + 3*i + j] = o.sigma(i, j);
        p[e] = o.p;
        vm[e] = tensor::vonMises(o.sigma);
        J[e] = o.theta;
        dT[e] = o.temperatureRise;
    }
    const int k = steps_.empty() ? 0 : steps_.back().first + 1;
    // Copy, append, replace: a kill at any instant leaves the previous
    // file intact (costs one copy of the file per step)
    const std::string tmp = copyToTemporary(h5File());
    {
        Hdf5File f(tmp, Hdf5File::Mode::readWrite);
        {
            Hdf5Group steps(f, "steps", false);
            Hdf5Group g(steps, std::to_string(k), true);
            g.writeAttribute("time", model.time);
            const auto u = nodeVectors(model, model.u);
            const auto v = nodeVectors(model, model.v);
            g.write("displacement", u.data(), m.nNodes(), 3);
            g.write("velocity", v.data(), m.nNodes(), 3);
            g.write("cauchyStress", sigma.data(), ne, 9);
            g.write("pressure", p.data(), ne);
            g.write("vonMises", vm.data(), ne);
            g.write("J", J.data(), ne);
            g.write("temperatureRise", dT.data(), ne);
            g.write("region", m.region.data(), ne);
            // The exact state for a restart: the model's snapshot
            Hdf5Group r(g, "restart", true);
            const ModelSnapshot state(model);
            for (int i = 0; i < ModelSnapshot::nParts; ++i)
            {
                const auto part = ModelSnapshot::Part(i);
                const std::vector<double>& x = state.part(part);
                r.write(ModelSnapshot::name(part), x.data(), x.size());
            }
        }   // groups closed before the file, so that close() flushes all
        f.close();
    }
    commitFile(tmp, h5File());
    steps_.emplace_back(k, model.time);
    writeXdmf(model);
    return k;
}


void solid::ResultWriter::writeXdmf(const Model& model) const
{
    const Mesh& m = model.mesh();
    const std::string h5 = h5File().substr(h5File().find_last_of('/') + 1);
    const int nn = m.nNodes(), ne = m.nElements();
    const std::string tmp = temporaryName(xdmfFile());
    std::ofstream os(tmp);
    if (!os)
    {
        throw SolidError
        (
            SolidError::Kind::io, "cannot write '" + tmp + "'"
        );
    }
    os  << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n"
        << "<Grid Name=\"solid\" GridType=\"Collection\" "
           "CollectionType=\"Temporal\">\n";
    auto item = [&](const std::string& path, int rows, int cols,
                    const char* type)
    {
        os  << "    <DataItem Dimensions=\"" << rows;
        if (cols > 1) os << " " << cols;
        os  << "\" NumberType=\"" << type << "\" Precision=\""
            << (type[0] == 'I' ? 4 : 8) << "\" Format=\"HDF\">" << h5 << ":"
            << path << "</DataItem>\n";
    };
    for (const auto& s : steps_)
    {
        const std::string g = "/steps/" + std::to_string(s.first) + "/";
        os  << "  <Grid Name=\"step" << s.first << "\">\n"
            << "   <Time Value=\"" << s.second << "\"/>\n"
            << "   <Topology TopologyType=\""
            << (m.axisymmetric() ? "Quadrilateral" : "Hexahedron")
            << "\" NumberOfElements=\"" << ne << "\">\n";
        item("/mesh/connectivity", ne, m.nen(), "Int");
        os  << "   </Topology>\n   <Geometry GeometryType=\"XYZ\">\n";
        item("/mesh/coordinates", nn, 3, "Float");
        os  << "   </Geometry>\n";
        const struct { const char* name; const char* type; bool node;
                       int cols; } fields[] =
        {
            {"displacement", "Vector", true, 3},
            {"velocity", "Vector", true, 3},
            {"cauchyStress", "Tensor", false, 9},
            {"pressure", "Scalar", false, 1},
            {"vonMises", "Scalar", false, 1},
            {"J", "Scalar", false, 1},
            {"temperatureRise", "Scalar", false, 1},
            {"region", "Scalar", false, 1}
        };
        for (const auto& f : fields)
        {
            os  << "   <Attribute Name=\"" << f.name << "\" AttributeType=\""
                << f.type << "\" Center=\"" << (f.node ? "Node" : "Cell")
                << "\">\n";
            item(g + f.name, f.node ? nn : ne, f.cols,
                 std::string(f.name) == "region" ? "Int" : "Float");
            os  << "   </Attribute>\n";
        }
        os  << "  </Grid>\n";
    }
    os  << "</Grid>\n</Domain>\n</Xdmf>\n";
    os.close();
    if (!os)
    {
        throw SolidError
        (
            SolidError::Kind::io, "cannot write '" + tmp + "'"
        );
    }
    commitFile(tmp, xdmfFile());
}


std::string solid::ResultWriter::newRunId()
{
    std::random_device device;
    std::string id;
    for (int i = 0; i < 4; ++i)
    {
        char word[9];
        std::snprintf(word, sizeof(word), "%08x", unsigned(device()));
        id += word;
    }
    return id;
}


void solid::ResultWriter::checkContinued
(
    const std::string& h5,
    const std::string& runId
)
{
    const Hdf5File f(h5, Hdf5File::Mode::readOnly);
    f.verify();
    if (runId.empty()) return;
    std::string found;
    for (const auto& t : f.texts())
    {
        if (t.first == "runId") found = t.second;
    }
    if (found != runId)
    {
        throw SolidError
        (
            SolidError::Kind::io, "'" + h5 + "' belongs to another run: "
          + (found.empty() ? std::string("it carries no run id")
             : "its run id is " + found)
          + ", the restart state's " + runId + " (a file copied from "
            "another case or run, or replaced since): a restart continues "
            "only the files of its own run"
        );
    }
}


std::vector<std::pair<int, double>> solid::ResultWriter::steps
(
    const std::string& h5
)
{
    const Hdf5File f(h5, Hdf5File::Mode::readOnly);
    const Hdf5Group g(f, "steps", false);
    std::vector<std::pair<int, double>> out;
    for (const std::string& name : g.members())
    {
        if
        (
            name.empty()
         || name.find_first_not_of("0123456789") != std::string::npos
         || name.size() > 9
        )
        {
            throw SolidError
            (
                SolidError::Kind::io, "'" + h5 + "': /steps holds '"
              + name + "', not a step number (not a result file of the "
                "solid library?)"
            );
        }
        const Hdf5Group s(g, name, false);
        out.emplace_back(std::stoi(name), s.readAttribute("time"));
    }
    std::sort(out.begin(), out.end());
    return out;
}


void solid::ResultWriter::restart(const std::string& h5, int k, Model& model)
{
    const Hdf5File f(h5, Hdf5File::Mode::readOnly);
    const Hdf5Group steps(f, "steps", false);
    const std::string name = std::to_string(k);
    if (!steps.has(name))
    {
        throw SolidError
        (
            SolidError::Kind::io, "restart: file '" + h5 + "' has no step "
          + name
        );
    }
    const Hdf5Group g(steps, name, false);
    const Hdf5Group r(g, "restart", false);
    // Every part checked against the model before the model is touched
    const auto expected = ModelSnapshot::sizes(model);
    ModelSnapshot state;
    for (int i = 0; i < ModelSnapshot::nParts; ++i)
    {
        const auto part = ModelSnapshot::Part(i);
        const std::string what = ModelSnapshot::name(part);
        state.part(part) = r.read(what);
        if (state.part(part).size() != expected[i])
        {
            throw SolidError
            (
                SolidError::Kind::io, "restart: '" + what + "' in '" + h5
              + "' step " + name + " has "
              + std::to_string(state.part(part).size())
              + " values, the model needs " + std::to_string(expected[i])
              + " (different mesh/materials?)"
            );
        }
    }
    state.setTime(g.readAttribute("time"));
    state.restore(model);
}
