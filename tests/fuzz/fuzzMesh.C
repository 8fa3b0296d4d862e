// libFuzzer harness: the solid library's own gmsh MSH reader
// (solid::readGmsh, ASCII MSH 4.1 and 2.2). The input is written to a file
// and read; the reader must either return a mesh that passed Mesh::check
// (every connectivity and set entry a valid node) or throw SolidError,
// without a crash or undefined behaviour.
#include "GmshReader.H"
#include "SolidError.H"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    static const std::string file =
        "fuzzMesh." + std::to_string(getpid()) + ".msh";
    {
        std::ofstream os(file, std::ios::binary);
        os.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    try
    {
        const solid::Mesh m = solid::readGmsh(file, 1.0);
        const int n = m.nNodes();
        for (int c : m.conn)
        {
            if (c < 0 || c >= n) __builtin_trap();
        }
        for (const auto& s : m.nodeSets)
        {
            for (int c : s.second) if (c < 0 || c >= n) __builtin_trap();
        }
        for (const auto& s : m.faceSets)
        {
            for (const auto& f : s.second)
            {
                for (int c : f) if (c < 0 || c >= n) __builtin_trap();
            }
        }
        if (int(m.conn.size()) != m.nen()*m.nElements()) __builtin_trap();
    }
    catch (const solid::SolidError&)
    {
    }
    std::remove(file.c_str());
    return 0;
}
