#include "Checkpoint.H"
#include "AtomicFile.H"
#include "SolidError.H"

#include <hdf5.h>

#include <string>
#include <sys/stat.h>

namespace
{

using solid::SolidError;

SolidError ioError(const std::string& msg)
{
    return SolidError(SolidError::Kind::io, msg);
}

struct H5File
{
    hid_t id;
    H5File(const std::string& name, unsigned mode, bool create)
    {
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
        id = create
            ? H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)
            : H5Fopen(name.c_str(), mode, H5P_DEFAULT);
        if (id < 0)
        {
            throw ioError
            (
                "cannot " + std::string(create ? "create" : "open")
              + " HDF5 file '" + name + "'"
            );
        }
    }
    //- Close now (flushes), reporting a failure
    void close()
    {
        const hid_t f = id;
        id = -1;
        if (H5Fclose(f) < 0) throw ioError("cannot close an HDF5 file");
    }
    ~H5File() { if (id >= 0) H5Fclose(id); }
};

struct Names
{
    std::vector<std::string> list;
};

herr_t collect(hid_t, const char* name, const H5L_info_t*, void* op)
{
    static_cast<Names*>(op)->list.emplace_back(name);
    return 0;
}

std::vector<std::string> members(hid_t g)
{
    Names n;
    hsize_t idx = 0;
    H5Literate(g, H5_INDEX_NAME, H5_ITER_NATIVE, &idx, collect, &n);
    return n.list;
}

herr_t visitDataset(hid_t, const char* name, const H5O_info_t* info, void* op)
{
    if (info->type == H5O_TYPE_DATASET)
    {
        static_cast<Names*>(op)->list.emplace_back(name);
    }
    return 0;
}

//- Paths of all datasets below g
std::vector<std::string> datasets(hid_t g)
{
    Names n;
    if (H5Ovisit(g, H5_INDEX_NAME, H5_ITER_NATIVE, visitDataset, &n) < 0)
    {
        throw ioError("cannot list the entries of a checkpoint");
    }
    return n.list;
}

} // namespace


bool solid::Checkpoint::exists(const std::string& file)
{
    struct stat s;
    return ::stat(file.c_str(), &s) == 0;
}


solid::Checkpoint solid::Checkpoint::read(const std::string& file)
{
    Checkpoint c(file);
    H5File f(file, H5F_ACC_RDONLY, false);
    for (const std::string& name : datasets(f.id))
    {
        const hid_t d = H5Dopen2(f.id, name.c_str(), H5P_DEFAULT);
        if (d < 0)
        {
            throw ioError("checkpoint '" + file + "': cannot open entry '"
                          + name + "'");
        }
        const hid_t space = H5Dget_space(d);
        const hssize_t n = H5Sget_simple_extent_npoints(space);
        std::vector<double> v(n > 0 ? n : 0);
        const herr_t st = n > 0
            ? H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                      v.data())
            : 0;
        H5Sclose(space);
        H5Dclose(d);
        if (n < 0 || st < 0)
        {
            throw ioError("checkpoint '" + file + "': cannot read entry '"
                          + name + "'");
        }
        c.data_[name] = std::move(v);
    }
    return c;
}


void solid::Checkpoint::write() const
{
    const std::string tmp = temporaryName(file_);
    {
        H5File f(tmp, 0, true);
        // Names with '/' create their groups
        const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
        H5Pset_create_intermediate_group(lcpl, 1);
        for (const auto& kv : data_)
        {
            const hsize_t n = kv.second.size();
            const hid_t space = H5Screate_simple(1, &n, nullptr);
            const hid_t d = H5Dcreate2
            (
                f.id, kv.first.c_str(), H5T_NATIVE_DOUBLE, space, lcpl,
                H5P_DEFAULT, H5P_DEFAULT
            );
            const herr_t st = d < 0 ? -1
              : n == 0 ? 0
              : H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                         kv.second.data());
            if (d >= 0) H5Dclose(d);
            H5Sclose(space);
            if (st < 0)
            {
                H5Pclose(lcpl);
                throw ioError("cannot write entry '" + kv.first + "' to '"
                              + tmp + "'");
            }
        }
        H5Pclose(lcpl);
        if (H5Fflush(f.id, H5F_SCOPE_GLOBAL) < 0)
        {
            throw ioError("cannot flush '" + tmp + "'");
        }
    }
    commitFile(tmp, file_);
}


const std::vector<double>& solid::Checkpoint::get
(
    const std::string& name, long expected
) const
{
    const auto it = data_.find(name);
    if (it == data_.end())
    {
        throw ioError("checkpoint '" + file_ + "': entry '" + name
                      + "' is missing");
    }
    if (expected >= 0 && long(it->second.size()) != expected)
    {
        throw ioError
        (
            "checkpoint '" + file_ + "': entry '" + name + "' has "
          + std::to_string(it->second.size()) + " values, expected "
          + std::to_string(expected) + " (a checkpoint of another mesh or "
            "model?)"
        );
    }
    return it->second;
}


Eigen::VectorXd solid::Checkpoint::vector
(
    const std::string& name, long expected
) const
{
    const std::vector<double>& v = get(name, expected);
    return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
}


void solid::Checkpoint::storeModel(const std::string& prefix, Model& model)
{
    set(prefix + "u", model.u);
    set(prefix + "v", model.v);
    set(prefix + "pressure", model.pressure);
    set(prefix + "time", model.time);
    set(prefix + "pointState", model.pointState().oldData());
    set(prefix + "elementState", model.elementState().oldData());
}


void solid::Checkpoint::restoreModel
(
    const std::string& prefix, Model& model
) const
{
    model.u = vector(prefix + "u", model.u.size());
    model.v = vector(prefix + "v", model.v.size());
    model.pressure = vector(prefix + "pressure", model.pressure.size());
    model.time = scalar(prefix + "time");
    auto& ps = model.pointState();
    auto& es = model.elementState();
    ps.oldData() = get(prefix + "pointState", ps.oldData().size());
    ps.currentData() = ps.oldData();
    es.oldData() = get(prefix + "elementState", es.oldData().size());
    es.currentData() = es.oldData();
}


int solid::truncateSteps(const std::string& h5, int n)
{
    // Which steps go: read only, so that a file with none (the usual
    // restart) is neither copied nor touched
    std::vector<std::string> remove;
    {
        H5File f(h5, H5F_ACC_RDONLY, false);
        if (H5Lexists(f.id, "steps", H5P_DEFAULT) <= 0) return 0;
        const hid_t g = H5Gopen2(f.id, "steps", H5P_DEFAULT);
        if (g < 0) throw ioError("cannot open /steps of '" + h5 + "'");
        for (const std::string& name : members(g))
        {
            const bool numeric =
                !name.empty() && name.size() <= 9
             && name.find_first_not_of("0123456789") == std::string::npos;
            if (numeric && std::stoi(name) >= n)
            {
                remove.push_back(name);
            }
        }
        H5Gclose(g);
    }
    if (remove.empty()) return 0;

    // Edited in a copy that replaces the file (AtomicFile.H): a run killed
    // during the edit leaves the file as it was
    const std::string tmp = copyToTemporary(h5);
    {
        H5File f(tmp, H5F_ACC_RDWR, false);
        const hid_t g = H5Gopen2(f.id, "steps", H5P_DEFAULT);
        if (g < 0) throw ioError("cannot open /steps of '" + tmp + "'");
        for (const std::string& name : remove)
        {
            if (H5Ldelete(g, name.c_str(), H5P_DEFAULT) < 0)
            {
                H5Gclose(g);
                throw ioError("cannot remove step " + name + " of '" + tmp
                              + "'");
            }
        }
        H5Gclose(g);
        f.close();
    }
    commitFile(tmp, h5);
    return int(remove.size());
}
