#include "mshFile.H"
#include "Pair.H"
#include "List.H"
#include "OSspecific.H"
#include "error.H"

#include <gmsh.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/statvfs.h>
#include <unistd.h>

namespace
{

//- Why the gmsh text file is incomplete, or empty if it is complete: the
//  sections ($Name ... $EndName) nested properly and closed, $Nodes and
//  $Elements among them, the file ending with a line end
std::string incomplete(const std::string& file)
{
    std::ifstream is(file, std::ios::binary);
    if (!is)
    {
        return "it cannot be read back";
    }
    std::vector<std::string> open;
    bool nodes = false, elements = false;
    std::string line;
    bool lastLineEnded = true;
    while (std::getline(is, line))
    {
        lastLineEnded = !is.eof();
        if (line.empty() || line[0] != '$') continue;
        while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
        {
            line.pop_back();
        }
        if (line.compare(0, 4, "$End") == 0)
        {
            const std::string name(line.substr(4));
            if (open.empty() || open.back() != name)
            {
                return "section end " + line + " without its start";
            }
            open.pop_back();
            nodes = nodes || name == "Nodes";
            elements = elements || name == "Elements";
        }
        else if (open.empty())
        {
            open.push_back(line.substr(1));
        }
    }
    if (!open.empty())
    {
        return "section $" + open.back() + " has no end";
    }
    if (!lastLineEnded)
    {
        return "its last line has no end";
    }
    if (!nodes || !elements)
    {
        return std::string("it has no ") + (nodes ? "$Elements" : "$Nodes")
          + " section";
    }
    return "";
}


//- Bytes free for an unprivileged user on the file system holding path
//  (for the message), or -1
//- Why writing to file fails, as the system says (strerror of errno), or
//  empty if it does not: gmsh::write reports no error (adv33 x11: a full
//  disk reported as an incomplete file, its cause not said). Blocks are
//  appended until a write fails (a full file system, a file size limit)
//  or 1 MB is written
std::string writeError(const std::string& file)
{
    const int fd = ::open(file.c_str(), O_WRONLY | O_APPEND);
    if (fd < 0)
    {
        return std::strerror(errno);
    }
    const std::vector<char> block(65536, '\n');
    std::string why;
    for (int i = 0; i < 16 && why.empty(); ++i)
    {
        if (::write(fd, block.data(), block.size()) < 0)
        {
            why = std::strerror(errno);
        }
    }
    if (why.empty() && ::fsync(fd) != 0)
    {
        why = std::strerror(errno);
    }
    ::close(fd);
    return why;
}


double bytesFree(const std::string& path)
{
    struct statvfs s;
    return ::statvfs(path.c_str(), &s) == 0
        ? double(s.f_bavail)*double(s.f_frsize) : -1;
}

} // namespace


Foam::fileName Foam::mshFile::temporaryName(const fileName& file)
{
    return file.path()/"." + file.nameLessExt() + "-tmp.msh";
}


Foam::fileName Foam::mshFile::writeTemporary(const fileName& file)
{
    mkDir(file.path());
    const fileName tmp(temporaryName(file));
    gmsh::write(tmp);
    const std::string why(incomplete(tmp));
    if (!why.empty())
    {
        const double size = Foam::fileSize(tmp);
        const std::string cause(writeError(tmp));
        Foam::rm(tmp);
        const double free = bytesFree(file.path());
        FatalErrorInFunction
            << "the gmsh file written for " << file << " is incomplete ("
            << why << ", " << size << " bytes): the write failed";
        if (!cause.empty())
        {
            FatalError
                << ": writing to " << tmp << " fails with '"
                << cause.c_str() << "'";
        }
        if (free >= 0)
        {
            FatalError
                << " (the file system holding it has " << free << " bytes"
                << " free)";
        }
        FatalError
            << ". Nothing was replaced: " << file << " is kept as it was"
            << exit(FatalError);
    }
    return tmp;
}


void Foam::mshFile::commit(const List<Pair<fileName>>& files)
{
    for (const Pair<fileName>& f : files)
    {
        const int fd = ::open(f.first().c_str(), O_RDONLY);
        if (fd < 0 || ::fsync(fd) != 0)
        {
            const std::string reason(std::strerror(errno));
            if (fd >= 0) ::close(fd);
            for (const Pair<fileName>& g : files) Foam::rm(g.first());
            FatalErrorInFunction
                << "cannot flush " << f.first() << " to disk (" << reason.c_str()
                << "): nothing was replaced, " << f.second() << " is kept as"
                << " it was" << exit(FatalError);
        }
        ::close(fd);
    }
    for (const Pair<fileName>& f : files)
    {
        if (!Foam::mv(f.first(), f.second()))
        {
            FatalErrorInFunction
                << "cannot move " << f.first() << " to " << f.second()
                << exit(FatalError);
        }
    }
}
