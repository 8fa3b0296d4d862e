// libFuzzer harness: reading the solid library's HDF5 result/restart file
// (ResultWriter::steps, ResultWriter::restart) when the file is truncated,
// as a killed writer without atomic writes, a full disk or an interrupted
// copy leaves it. A valid file of a small model (three steps) is written
// once; each input chooses the length it is cut to (first 4 bytes,
// modulo the file size) and the step to restart from (5th byte). The
// reader must restore the step or throw SolidError: no crash.
#include "Loads.H"
#include "Model.H"
#include "ResultWriter.H"
#include "SolidError.H"
#include "StaticSolver.H"
#include "Material.H"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

namespace
{

std::unique_ptr<solid::Model> model()
{
    std::unique_ptr<solid::Model> m
    (
        new solid::Model(solid::Mesh::rectangle(2, 2, 0, 1e-5, 0, 1e-5))
    );
    solid::MaterialParameters p;
    p.name = "solid";
    p.C10 = 13.33;
    p.d0 = 0;
    p.branches = {{862.22, 0.5}};
    m->setMaterial("solid", solid::Material::create(p));
    m->fix("left", 0);
    m->fix("bottom", 1);
    m->add(std::make_shared<solid::PressureLoad>("top",
        [](double t) { return 50.0*t; }));
    m->initialise();
    return m;
}

const std::string& good()
{
    static std::string bytes;
    if (bytes.empty())
    {
        const std::string base = "fuzzResult" + std::to_string(getpid());
        auto m = model();
        solid::StaticSolver s(*m);
        solid::ResultWriter w(base, *m);
        w.write(*m);
        for (int i = 0; i < 2; ++i)
        {
            s.step(0.1);
            w.write(*m);
        }
        std::ifstream is(base + ".h5", std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(is), {});
        std::remove((base + ".h5").c_str());
        std::remove((base + ".xmf").c_str());
    }
    return bytes;
}

} // namespace


extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const std::string& full = good();
    if (size < 5) return 0;
    const uint32_t cut =
        (uint32_t(data[0]) | uint32_t(data[1]) << 8 | uint32_t(data[2]) << 16
       | uint32_t(data[3]) << 24) % (full.size() + 1);
    const int step = data[4] % 4;
    const std::string file = "fuzzCut" + std::to_string(getpid()) + ".h5";
    {
        std::ofstream os(file, std::ios::binary);
        os.write(full.data(), cut);
    }
    try
    {
        const auto steps = solid::ResultWriter::steps(file);
        auto m = model();
        solid::ResultWriter::restart(file, step, *m);
        (void)steps;
    }
    catch (const solid::SolidError&)
    {
    }
    std::remove(file.c_str());
    return 0;
}
