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


std::string solid::spaceNote
(
    const std::string& file,
    const unsigned long long needed
)
{
    std::filesystem::path dir = std::filesystem::path(file).parent_path();
    if (dir.empty())
    {
        dir = ".";
    }
    std::error_code ec;
    const std::filesystem::space_info sp = std::filesystem::space(dir, ec);
    if (!ec && sp.available < needed + (1ull << 20))
    {
        return " (the file system of '" + dir.string() + "' has "
            + std::to_string(sp.available) + " bytes free"
            + (needed ? ", the write needs " + std::to_string(needed) : "")
            + ": " + std::strerror(ENOSPC) + ")";
    }
    if (::access(dir.c_str(), W_OK) != 0)
    {
        return " ('" + dir.string() + "': " + std::strerror(errno) + ")";
    }
    return std::string();
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
        std::error_code ec;
        const auto size = std::filesystem::file_size(file, ec);
        throw SolidError
        (
            SolidError::Kind::io, "cannot copy '" + file + "' to '" + tmp
          + "': " + e.what() + spaceNote(tmp, ec ? 0 : size)
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
