#include "ResultWriter.H"
#include "AtomicFile.H"
#include "SolidError.H"

#include <hdf5.h>

#include <algorithm>
#include <fstream>

namespace
{

using solid::SolidError;

void check(herr_t status, const std::string& what)
{
    if (status < 0)
    {
        throw SolidError(SolidError::Kind::io, "HDF5: failed to " + what);
    }
}

hid_t checkId(hid_t id, const std::string& what)
{
    if (id < 0)
    {
        throw SolidError(SolidError::Kind::io, "HDF5: failed to " + what);
    }
    return id;
}

// RAII file handle
struct File
{
    enum class Mode { create, readWrite, readOnly };
    hid_t id;
    File(const std::string& name, Mode mode)
    {
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
        id = mode == Mode::create
            ? H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)
            : H5Fopen(name.c_str(), mode == Mode::readWrite ? H5F_ACC_RDWR
                      : H5F_ACC_RDONLY, H5P_DEFAULT);
        checkId(id, "open '" + name + "'");
    }
    //- Close now (flushes), reporting a failure
    void close()
    {
        const hid_t f = id;
        id = -1;
        check(H5Fclose(f), "close file");
    }
    ~File() { if (id >= 0) H5Fclose(id); }
};

struct Group
{
    hid_t id;
    Group(hid_t parent, const std::string& name, bool create)
    {
        id = create
            ? H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT,
                         H5P_DEFAULT)
            : H5Gopen2(parent, name.c_str(), H5P_DEFAULT);
        checkId(id, (create ? "create group " : "open group ") + name);
    }
    ~Group() { H5Gclose(id); }
};

template<class T>
void writeArray
(
    hid_t g, const std::string& name, const T* data, hsize_t rows,
    hsize_t cols
)
{
    const hid_t type = std::is_same<T, int>::value ? H5T_NATIVE_INT
                                                   : H5T_NATIVE_DOUBLE;
    const hsize_t dims[2] = {rows, cols};
    const hid_t space = H5Screate_simple(cols > 1 ? 2 : 1, dims, nullptr);
    const hid_t d = checkId
    (
        H5Dcreate2(g, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT,
                   H5P_DEFAULT),
        "create dataset " + name
    );
    if (rows*cols > 0)
    {
        check(H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
              "write " + name);
    }
    H5Dclose(d);
    H5Sclose(space);
}

std::vector<double> readArray(hid_t g, const std::string& name)
{
    const hid_t d = checkId(H5Dopen2(g, name.c_str(), H5P_DEFAULT),
                            "open dataset " + name);
    const hid_t space = H5Dget_space(d);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    std::vector<double> v(n);
    if (n > 0)
    {
        check(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                      v.data()), "read " + name);
    }
    H5Sclose(space);
    H5Dclose(d);
    return v;
}

void writeTime(hid_t g, double t)
{
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(g, "time", H5T_NATIVE_DOUBLE, space,
                               H5P_DEFAULT, H5P_DEFAULT);
    check(H5Awrite(a, H5T_NATIVE_DOUBLE, &t), "write time");
    H5Aclose(a);
    H5Sclose(space);
}

double readTime(hid_t g)
{
    double t = 0;
    const hid_t a = checkId(H5Aopen(g, "time", H5P_DEFAULT), "open time");
    check(H5Aread(a, H5T_NATIVE_DOUBLE, &t), "read time");
    H5Aclose(a);
    return t;
}

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
    bool append
)
:
    base_(base)
{
    if (append)
    {
        // The .xmf is derived from the .h5: a run killed between the two
        // renames of write() left it one step behind
        steps_ = steps(h5File());
        writeXdmf(model);
        return;
    }
    const std::string tmp = temporaryName(h5File());
    {
        File f(tmp, File::Mode::create);
        {
            Group mesh(f.id, "mesh", true);
            const Mesh& m = model.mesh();
            std::vector<double> X(3*m.nNodes());
            for (int n = 0; n < m.nNodes(); ++n)
                for (int i = 0; i < 3; ++i) X[3*n + i] = m.X[n](i);
            writeArray(mesh.id, "coordinates", X.data(), m.nNodes(), 3);
            writeArray(mesh.id, "connectivity", m.conn.data(),
                       m.nElements(), m.nen());
            writeArray(mesh.id, "region", m.region.data(), m.nElements(), 1);
            Group s(f.id, "steps", true);
        }
        f.close();
    }
    commitFile(tmp, h5File());
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
        File f(tmp, File::Mode::readWrite);
        {
            Group steps(f.id, "steps", false);
            Group g(steps.id, std::to_string(k), true);
            writeTime(g.id, model.time);
            const auto u = nodeVectors(model, model.u);
            const auto v = nodeVectors(model, model.v);
            writeArray(g.id, "displacement", u.data(), m.nNodes(), 3);
            writeArray(g.id, "velocity", v.data(), m.nNodes(), 3);
            writeArray(g.id, "cauchyStress", sigma.data(), ne, 9);
            writeArray(g.id, "pressure", p.data(), ne, 1);
            writeArray(g.id, "vonMises", vm.data(), ne, 1);
            writeArray(g.id, "J", J.data(), ne, 1);
            writeArray(g.id, "temperatureRise", dT.data(), ne, 1);
            writeArray(g.id, "region", m.region.data(), ne, 1);
            Group r(g.id, "restart", true);
            writeArray(r.id, "u", model.u.data(), model.u.size(), 1);
            writeArray(r.id, "v", model.v.data(), model.v.size(), 1);
            writeArray(r.id, "pressure", model.pressure.data(),
                       model.pressure.size(), 1);
            const auto& ps = model.pointState().oldData();
            const auto& es = model.elementState().oldData();
            writeArray(r.id, "pointState", ps.data(), ps.size(), 1);
            writeArray(r.id, "elementState", es.data(), es.size(), 1);
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


std::vector<std::pair<int, double>> solid::ResultWriter::steps
(
    const std::string& h5
)
{
    File f(h5, File::Mode::readOnly);
    Group g(f.id, "steps", false);
    hsize_t n = 0;
    check(H5Gget_num_objs(g.id, &n), "count steps");
    std::vector<std::pair<int, double>> out;
    for (hsize_t i = 0; i < n; ++i)
    {
        char name[64] = "";
        if (H5Gget_objname_by_idx(g.id, i, name, sizeof(name)) <= 0
         || std::string(name).find_first_not_of("0123456789") !=
                std::string::npos
         || std::string(name).size() > 9)
        {
            throw SolidError
            (
                SolidError::Kind::io, "'" + h5 + "': /steps holds '"
              + std::string(name) + "', not a step number (not a result "
                "file of the solid library?)"
            );
        }
        Group s(g.id, name, false);
        out.emplace_back(std::stoi(name), readTime(s.id));
    }
    std::sort(out.begin(), out.end());
    return out;
}


void solid::ResultWriter::restart(const std::string& h5, int k, Model& model)
{
    File f(h5, File::Mode::readOnly);
    Group steps(f.id, "steps", false);
    const std::string name = std::to_string(k);
    if (H5Lexists(steps.id, name.c_str(), H5P_DEFAULT) <= 0)
    {
        throw SolidError
        (
            SolidError::Kind::io, "restart: file '" + h5 + "' has no step "
          + name
        );
    }
    Group g(steps.id, name, false);
    Group r(g.id, "restart", false);
    auto load = [&](const char* what, std::size_t expected)
    {
        std::vector<double> v = readArray(r.id, what);
        if (v.size() != expected)
        {
            throw SolidError
            (
                SolidError::Kind::io, "restart: '" + std::string(what)
              + "' in '" + h5 + "' step " + name + " has "
              + std::to_string(v.size()) + " values, the model needs "
              + std::to_string(expected) + " (different mesh/materials?)"
            );
        }
        return v;
    };
    const auto u = load("u", model.u.size());
    const auto v = load("v", model.v.size());
    const auto p = load("pressure", model.pressure.size());
    const auto ps = load("pointState", model.pointState().oldData().size());
    const auto es =
        load("elementState", model.elementState().oldData().size());
    model.u = Eigen::Map<const Eigen::VectorXd>(u.data(), u.size());
    model.v = Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
    model.pressure = Eigen::Map<const Eigen::VectorXd>(p.data(), p.size());
    model.pointState().oldData() = ps;
    model.elementState().oldData() = es;
    model.pointState().revert();
    model.elementState().revert();
    model.time = readTime(g.id);
}
