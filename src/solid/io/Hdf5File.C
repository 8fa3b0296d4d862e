#include "Hdf5File.H"
#include "AtomicFile.H"
#include "SolidError.H"

#include "fileKind.H"

#include <hdf5.h>
#include <string>

namespace
{

hid_t openFile(const std::string& name, solid::Hdf5File::Mode mode)
{
    using Mode = solid::Hdf5File::Mode;
    // A FIFO, socket or device blocks the open without end (issue 19,
    // adv28 ir06: solidToFoam given a FIFO as its results file waited
    // without output): looked at first (src/foamTools/fileKind.H)
    const std::string kind(fileKind::notARegularFile(name));
    if (!kind.empty())
    {
        throw solid::SolidError
        (
            solid::SolidError::Kind::io, "cannot "
          + std::string(mode == Mode::create ? "create" : "open")
          + " HDF5 file '" + name + "': it is " + kind + ", not a file"
          + (kind == "a directory" ? std::string()
             : kind == "a device"
             ? std::string(" (a device such as /dev/zero gives bytes without"
                           " end or waits for input; adv48b g52)")
             : std::string(" (opening it would wait without end for the"
                           " other side)"))
        );
    }
    // No clean-up of the library at exit: a file whose close failed (a
    // full disk) stays registered, and HDF5's atexit handler closed it
    // again after the error had been reported, crashing in H5F__close_cb
    // (adv32 d02, d04: sigSegv, exit 139). Every write of ours goes to a
    // temporary file closed and renamed in its scope (AtomicFile.H), so a
    // file still open at exit is one whose write failed or was abandoned.
    // H5dont_atexit works only before the library's first call: here
    static const bool noCleanupAtExit = H5dont_atexit() >= 0;
    static_cast<void>(noCleanupAtExit);
    // Failures are reported as SolidErrors naming the file, not as the
    // library's error stack on stderr
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    // Files in the format of HDF5 1.8 and later: its superblock, object
    // headers (with the attributes) and group indices carry checksums,
    // verified when read, as the datasets do (Hdf5Group::write)
    const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_LATEST);
    const hid_t id = mode == Mode::create
        ? H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl)
        : H5Fopen(name.c_str(), mode == Mode::readWrite ? H5F_ACC_RDWR
                  : H5F_ACC_RDONLY, H5P_DEFAULT);
    H5Pclose(fapl);
    if (id < 0)
    {
        throw solid::SolidError
        (
            solid::SolidError::Kind::io, "cannot "
          + std::string(mode == Mode::create ? "create" : "open")
          + " HDF5 file '" + name + "'"
          // a full disk or an unwritable folder named (adv38 x54)
          + (mode == Mode::create ? solid::spaceNote(name)
             : " (missing, truncated, damaged or not HDF5)")
        );
    }
    return id;
}

} // namespace


solid::Hdf5File::Hdf5File(const std::string& name, Mode mode)
:
    Hdf5Group(openFile(name, mode), name)
{}
