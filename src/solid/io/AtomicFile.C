#include "AtomicFile.H"
#include "SolidError.H"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <unistd.h>

std::string solid::temporaryName(const std::string& file)
{
    return file + ".tmp";
}


std::string solid::copyToTemporary(const std::string& file)
{
    const std::string tmp = temporaryName(file);
    try
    {
        std::filesystem::copy_file
        (
            file, tmp, std::filesystem::copy_options::overwrite_existing
        );
    }
    catch (const std::filesystem::filesystem_error& e)
    {
        throw SolidError
        (
            SolidError::Kind::io, "cannot copy '" + file + "' to '" + tmp
          + "': " + e.what()
        );
    }
    return tmp;
}


void solid::commitFile(const std::string& tmp, const std::string& target)
{
    // The data on disk before the rename makes it visible
    const int fd = ::open(tmp.c_str(), O_RDONLY);
    if (fd < 0 || ::fsync(fd) != 0)
    {
        const std::string reason = std::strerror(errno);
        if (fd >= 0) ::close(fd);
        throw SolidError
        (
            SolidError::Kind::io, "cannot flush '" + tmp + "': " + reason
        );
    }
    ::close(fd);
    if (std::rename(tmp.c_str(), target.c_str()) != 0)
    {
        throw SolidError
        (
            SolidError::Kind::io, "cannot rename '" + tmp + "' to '"
          + target + "': " + std::strerror(errno)
        );
    }
}
