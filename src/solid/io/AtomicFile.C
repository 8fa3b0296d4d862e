#include "AtomicFile.H"
#include "SolidError.H"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
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
        // A full file system said first: the library reports a copy cut
        // short as "Input/output error", and its text repeats both paths,
        // which put the note past what a reader of the first lines saw
        // (adv48a, adv37 w29)
        const std::string note(spaceNote(tmp, ec ? 0 : size));
        throw SolidError
        (
            SolidError::Kind::io, "cannot copy '" + file + "' to '" + tmp
          + "': "
          + (
                note.find(" bytes free") == std::string::npos
              ? std::string(e.what()) + note
              : "no space left on the file system" + note
            )
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


bool solid::ownCopy(const std::string& file)
{
    struct stat st;
    if (::stat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
    {
        return false;
    }
    if (st.st_nlink <= 1)
    {
        return false;
    }
    commitFile(copyToTemporary(file), file);
    return true;
}
