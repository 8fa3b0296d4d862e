#include "Hdf5Group.H"
#include "SolidError.H"
#include "AtomicFile.H"
#include "fileDigest.H"

#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <type_traits>

static_assert
(
    std::is_same<hid_t, std::int64_t>::value,
    "Hdf5Group stores hid_t as std::int64_t (HDF5 >= 1.10)"
);

namespace
{

//- Whether HDF5's error stack (of the call that failed last) holds a
//  failed checksum: a damaged object header, group index or superblock
//  (HDF5: "incorrect metadata checksum ...")
herr_t findChecksum(unsigned, const H5E_error2_t* e, void* out)
{
    if (e && e->desc && std::string(e->desc).find("checksum")
     != std::string::npos)
    {
        *static_cast<bool*>(out) = true;
    }
    return 0;
}

bool checksumFailed()
{
    bool found = false;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, findChecksum, &found);
    return found;
}

//- The words a failure whose error stack holds a failed checksum adds
const char* const damagedNote =
    " (a checksum of the file's structure (an object header, a group's"
    " index) does not match: the file is damaged)";

herr_t collectLink(hid_t, const char* name, const H5L_info_t*, void* out)
{
    static_cast<std::vector<std::string>*>(out)->emplace_back(name);
    return 0;
}

herr_t collectDataset
(
    hid_t, const char* name, const H5O_info_t* info, void* out
)
{
    if (info->type == H5O_TYPE_DATASET)
    {
        static_cast<std::vector<std::string>*>(out)->emplace_back(name);
    }
    return 0;
}

herr_t collectAttribute(hid_t, const char* name, const H5A_info_t*, void* out)
{
    static_cast<std::vector<std::string>*>(out)->emplace_back(name);
    return 0;
}

//- Read every attribute of an open object (verifying its checksum);
//  false if one cannot be read
bool readAttributes(hid_t obj)
{
    std::vector<std::string> names;
    hsize_t idx = 0;
    if
    (
        H5Aiterate2
        (
            obj, H5_INDEX_NAME, H5_ITER_INC, &idx, collectAttribute, &names
        ) < 0
    )
    {
        return false;
    }
    for (const std::string& name : names)
    {
        const hid_t a = H5Aopen(obj, name.c_str(), H5P_DEFAULT);
        const hid_t type = a < 0 ? -1 : H5Aget_type(a);
        const hid_t space = a < 0 ? -1 : H5Aget_space(a);
        const hssize_t n = space < 0 ? -1 : H5Sget_simple_extent_npoints(space);
        const std::size_t size = type < 0 ? 0 : H5Tget_size(type);
        bool ok = n >= 0 && size > 0 && H5Tis_variable_str(type) == 0;
        if (ok)
        {
            std::vector<char> buffer(std::size_t(n)*size + 1);
            ok = H5Aread(a, type, buffer.data()) >= 0;
        }
        if (space >= 0) H5Sclose(space);
        if (type >= 0) H5Tclose(type);
        if (a >= 0) H5Aclose(a);
        if (!ok) return false;
    }
    return true;
}

//- The 64-bit digest of a dataset's values (FNV-1a, fileDigest::add, over
//  the bytes of each value as a double, in order, then the rows and
//  columns): stored as the dataset's attribute digestName, compared at
//  every read. Fletcher-32,
//  HDF5's filter, sums 16-bit words modulo 65535, so a word 0x0000 turned
//  into 0xffff (or back) passes it (zeros, most of a step at rest); this
//  digest sees any change of a byte's value or place
const char* const digestName = "digest64";

template<class T>
std::uint64_t digest(const T* data, std::size_t n, hsize_t rows, hsize_t cols)
{
    std::uint64_t h = fileDigest::basis;
    for (std::size_t i = 0; i < n; ++i)
    {
        const double v = double(data[i]);
        h = fileDigest::add(h, &v, sizeof v);
    }
    const std::uint64_t shape[2] = {rows, cols};
    return fileDigest::add(h, shape, sizeof shape);
}

} // namespace


solid::Hdf5Group::Hdf5Group(std::int64_t id, const std::string& file)
:
    id_(id),
    isFile_(true),
    file_(file),
    path_("/")
{}


solid::Hdf5Group::Hdf5Group
(
    const Hdf5Group& parent,
    const std::string& name,
    bool create
)
:
    id_(-1),
    isFile_(false),
    file_(parent.file_),
    path_(parent.where(name))
{
    id_ = create
        ? H5Gcreate2(parent.id_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT,
                     H5P_DEFAULT)
        : H5Gopen2(parent.id_, name.c_str(), H5P_DEFAULT);
    if (id_ < 0)
    {
        const bool damaged = checksumFailed();
        throw SolidError
        (
            SolidError::Kind::io, "HDF5 file '" + file_ + "': cannot "
          + (create ? "create" : "open") + " group " + path_
          + (damaged ? damagedNote : "")
        );
    }
}


solid::Hdf5Group::~Hdf5Group()
{
    if (id_ >= 0)
    {
        isFile_ ? H5Fclose(id_) : H5Gclose(id_);
    }
}


void solid::Hdf5Group::closeNow()
{
    const hid_t id = id_;
    id_ = -1;
    check((isFile_ ? H5Fclose(id) : H5Gclose(id)) >= 0, "close");
}


void solid::Hdf5Group::check(bool ok, const std::string& what) const
{
    if (!ok)
    {
        // A failed checksum of the file's structure said as damage (adv46b
        // d49 (b): a flipped bit in an object header was "cannot open
        // dataset ... (missing?)", "cannot list the members of ...")
        const bool damaged =
            what.find("damaged") == std::string::npos && checksumFailed();
        throw SolidError
        (
            SolidError::Kind::io, "HDF5 file '" + file_ + "': cannot " + what
          + (damaged ? damagedNote : "") + spaceNote(file_)
        );
    }
}


std::string solid::Hdf5Group::where(const std::string& name) const
{
    if (!name.empty() && name[0] == '/') return name;
    return path_ == "/" ? "/" + name : path_ + "/" + name;
}


bool solid::Hdf5Group::has(const std::string& name) const
{
    return H5Lexists(id_, name.c_str(), H5P_DEFAULT) > 0;
}


std::vector<std::string> solid::Hdf5Group::members() const
{
    std::vector<std::string> names;
    hsize_t idx = 0;
    check
    (
        H5Literate(id_, H5_INDEX_NAME, H5_ITER_INC, &idx, collectLink, &names)
        >= 0,
        "list the members of " + path_
    );
    return names;
}


std::vector<std::string> solid::Hdf5Group::datasets() const
{
    std::vector<std::string> names;
    check
    (
        H5Ovisit(id_, H5_INDEX_NAME, H5_ITER_INC, collectDataset, &names)
        >= 0,
        "list the datasets below " + path_
    );
    return names;
}


void solid::Hdf5Group::remove(const std::string& name)
{
    check
    (
        H5Ldelete(id_, name.c_str(), H5P_DEFAULT) >= 0,
        "remove " + where(name)
    );
}


template<class T>
void solid::Hdf5Group::writeData
(
    const std::string& name,
    const T* data,
    std::size_t rows,
    std::size_t cols
)
{
    const hid_t type =
        std::is_same<T, int>::value ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE;
    const hsize_t dims[2] = {rows, cols};
    const hid_t space = H5Screate_simple(cols > 1 ? 2 : 1, dims, nullptr);
    // A name with '/' creates its groups (checkpoint entries)
    const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
    H5Pset_create_intermediate_group(lcpl, 1);
    // A Fletcher-32 checksum over the data (one chunk: the whole
    // dataset), verified by HDF5 at every read: damaged bytes are an
    // error, never values (an empty dataset has no chunk to check)
    const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    if (rows*cols > 0)
    {
        H5Pset_chunk(dcpl, cols > 1 ? 2 : 1, dims);
        H5Pset_fletcher32(dcpl);
    }
    const hid_t d = H5Dcreate2
    (
        id_, name.c_str(), type, space, lcpl, dcpl, H5P_DEFAULT
    );
    H5Pclose(dcpl);
    H5Pclose(lcpl);
    // An empty dataset has nothing to write
    bool ok = d >= 0
     && (rows*cols == 0
      || H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0);
    // The digest of the values (read() compares it); an empty dataset has
    // none
    if (ok && rows*cols > 0)
    {
        const std::uint64_t h =
            digest(data, rows*cols, rows, cols > 1 ? cols : 1);
        const hid_t as = H5Screate(H5S_SCALAR);
        const hid_t a = H5Acreate2
        (
            d, digestName, H5T_NATIVE_UINT64, as, H5P_DEFAULT, H5P_DEFAULT
        );
        ok = a >= 0 && H5Awrite(a, H5T_NATIVE_UINT64, &h) >= 0;
        if (a >= 0) H5Aclose(a);
        H5Sclose(as);
    }
    if (d >= 0) H5Dclose(d);
    H5Sclose(space);
    check(ok, "write dataset " + where(name));
}


void solid::Hdf5Group::write
(
    const std::string& name,
    const double* data,
    std::size_t rows,
    std::size_t cols
)
{
    writeData(name, data, rows, cols);
}


void solid::Hdf5Group::write
(
    const std::string& name,
    const int* data,
    std::size_t rows,
    std::size_t cols
)
{
    writeData(name, data, rows, cols);
}


std::vector<double> solid::Hdf5Group::read
(
    const std::string& name,
    std::size_t* rows,
    std::size_t* cols
) const
{
    const hid_t d = H5Dopen2(id_, name.c_str(), H5P_DEFAULT);
    if (d < 0)
    {
        // damage first (has() clears the error stack); a dataset its group
        // lists but that cannot be opened is damaged too
        const bool damaged = checksumFailed();
        check
        (
            false,
            "open dataset " + where(name)
          + (
                damaged ? damagedNote
              : has(name)
              ? " (its group lists it, but it cannot be opened: the file"
                " is damaged)"
              : " (missing?)"
            )
        );
    }
    const hid_t space = H5Dget_space(d);
    hsize_t dims[2] = {0, 1};
    const int rank = space < 0 ? -1
      : H5Sget_simple_extent_ndims(space) > 2 ? -1
      : H5Sget_simple_extent_dims(space, dims, nullptr);
    const hssize_t n = rank < 0 ? -1 : H5Sget_simple_extent_npoints(space);
    std::vector<double> v(n > 0 ? n : 0);
    const bool ok = n >= 0
     && (n == 0
      || H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                 v.data()) >= 0);
    if (space >= 0) H5Sclose(space);
    // The digest of the values, if the file has one (files of earlier
    // builds have none: read unchecked)
    bool digestOk = true;
    if (ok && H5Aexists(d, digestName) > 0)
    {
        std::uint64_t stored = 0;
        const hid_t a = H5Aopen(d, digestName, H5P_DEFAULT);
        const bool read =
            a >= 0 && H5Aread(a, H5T_NATIVE_UINT64, &stored) >= 0;
        if (a >= 0) H5Aclose(a);
        digestOk = read
         && stored
         == digest
            (
                v.data(), v.size(), rank > 0 ? dims[0] : 1,
                rank > 1 ? dims[1] : 1
            );
    }
    H5Dclose(d);
    check
    (
        ok,
        "read dataset " + where(name)
      + " (its checksum does not match: the file is damaged)"
    );
    check
    (
        digestOk,
        "read dataset " + where(name)
      + " (its values do not match their digest " + digestName
      + ": the file is damaged)"
    );
    if (rows) *rows = rank > 0 ? dims[0] : 1;
    if (cols) *cols = rank > 1 ? dims[1] : 1;
    return v;
}


void solid::Hdf5Group::writeAttribute(const std::string& name, double value)
{
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2
    (
        id_, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT
    );
    const bool ok = a >= 0 && H5Awrite(a, H5T_NATIVE_DOUBLE, &value) >= 0;
    if (a >= 0) H5Aclose(a);
    H5Sclose(space);
    check(ok, "write attribute " + name + " of " + path_);
}


double solid::Hdf5Group::readAttribute(const std::string& name) const
{
    double value = 0;
    const hid_t a = H5Aopen(id_, name.c_str(), H5P_DEFAULT);
    const bool ok = a >= 0 && H5Aread(a, H5T_NATIVE_DOUBLE, &value) >= 0;
    if (a >= 0) H5Aclose(a);
    check(ok, "read attribute " + name + " of " + path_);
    return value;
}


void solid::Hdf5Group::writeText
(
    const std::string& name,
    const std::string& text
)
{
    // A fixed-length string of the text's size (HDF5 refuses size 0)
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, text.empty() ? 1 : text.size());
    H5Tset_strpad(type, H5T_STR_NULLPAD);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2
    (
        id_, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT
    );
    const std::string data = text.empty() ? std::string(1, '\0') : text;
    const bool ok = a >= 0 && H5Awrite(a, type, data.data()) >= 0;
    if (a >= 0) H5Aclose(a);
    H5Sclose(space);
    H5Tclose(type);
    check(ok, "write text attribute " + name + " of " + path_);
}


std::vector<std::pair<std::string, std::string>>
solid::Hdf5Group::texts() const
{
    std::vector<std::string> names;
    hsize_t idx = 0;
    check
    (
        H5Aiterate2
        (
            id_, H5_INDEX_NAME, H5_ITER_INC, &idx, collectAttribute, &names
        ) >= 0,
        "list the attributes of " + path_
    );
    std::vector<std::pair<std::string, std::string>> result;
    for (const std::string& name : names)
    {
        const hid_t a = H5Aopen(id_, name.c_str(), H5P_DEFAULT);
        check(a >= 0, "open attribute " + name + " of " + path_);
        const hid_t type = H5Aget_type(a);
        const bool isText =
            type >= 0 && H5Tget_class(type) == H5T_STRING
         && H5Tis_variable_str(type) == 0;
        bool ok = true;
        std::string text;
        if (isText)
        {
            text.resize(H5Tget_size(type));
            ok = H5Aread(a, type, &text[0]) >= 0;
            text.resize(std::min(text.size(), text.find('\0')));
        }
        if (type >= 0) H5Tclose(type);
        H5Aclose(a);
        check(ok, "read text attribute " + name + " of " + path_);
        if (isText) result.emplace_back(name, text);
    }
    return result;
}


void solid::Hdf5Group::verify() const
{
    check
    (
        readAttributes(id_),
        "read the attributes of " + path_
      + " (a checksum does not match: the file is damaged)"
    );
    for (const std::string& name : members())
    {
        const hid_t obj = H5Oopen(id_, name.c_str(), H5P_DEFAULT);
        const H5I_type_t type = obj < 0 ? H5I_BADID : H5Iget_type(obj);
        if (obj >= 0) H5Oclose(obj);
        check
        (
            type == H5I_GROUP || type == H5I_DATASET,
            "open " + where(name)
          + " (its header's checksum does not match: the file is damaged)"
        );
        if (type == H5I_GROUP)
        {
            Hdf5Group(*this, name, false).verify();
        }
        else
        {
            const hid_t d = H5Dopen2(id_, name.c_str(), H5P_DEFAULT);
            const bool ok = d >= 0 && readAttributes(d);
            if (d >= 0) H5Dclose(d);
            check
            (
                ok,
                "read the attributes of dataset " + where(name)
              + " (a checksum does not match: the file is damaged)"
            );
            read(name);
        }
    }
}
