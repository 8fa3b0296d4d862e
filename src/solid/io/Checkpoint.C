#include "Checkpoint.H"
#include "AtomicFile.H"
#include "Hdf5File.H"
#include "SolidError.H"

#include <string>
#include <sys/stat.h>

namespace
{

solid::SolidError ioError(const std::string& msg)
{
    return solid::SolidError(solid::SolidError::Kind::io, msg);
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
    const Hdf5File f(file, Hdf5File::Mode::readOnly);
    for (const std::string& name : f.datasets())
    {
        c.data_[name] = f.read(name);
    }
    for (const auto& t : f.texts())
    {
        c.texts_[t.first] = t.second;
    }
    return c;
}


void solid::Checkpoint::write() const
{
    const std::string tmp = temporaryName(file_);
    {
        Hdf5File f(tmp, Hdf5File::Mode::create);
        // Names with '/' create their groups
        for (const auto& kv : data_)
        {
            f.write(kv.first, kv.second.data(), kv.second.size());
        }
        for (const auto& kv : texts_)
        {
            f.writeText(kv.first, kv.second);
        }
        f.close();
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


const std::string& solid::Checkpoint::text(const std::string& name) const
{
    const auto it = texts_.find(name);
    if (it == texts_.end())
    {
        throw ioError("checkpoint '" + file_ + "': text '" + name
                      + "' is missing");
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


void solid::Checkpoint::set
(
    const std::string& prefix,
    const ModelSnapshot& state
)
{
    for (int i = 0; i < ModelSnapshot::nParts; ++i)
    {
        const auto part = ModelSnapshot::Part(i);
        set(prefix + ModelSnapshot::name(part), state.part(part));
    }
    set(prefix + "time", state.time());
}


solid::ModelSnapshot solid::Checkpoint::snapshot
(
    const std::string& prefix,
    const Model& model
) const
{
    const auto expected = ModelSnapshot::sizes(model);
    ModelSnapshot state;
    for (int i = 0; i < ModelSnapshot::nParts; ++i)
    {
        const auto part = ModelSnapshot::Part(i);
        state.part(part) =
            get(prefix + ModelSnapshot::name(part), long(expected[i]));
    }
    state.setTime(scalar(prefix + "time"));
    return state;
}


int solid::truncateSteps(const std::string& h5, int n)
{
    // Which steps go: read only, so that a file with none (the usual
    // restart) is neither copied nor touched
    std::vector<std::string> remove;
    {
        const Hdf5File f(h5, Hdf5File::Mode::readOnly);
        if (!f.has("steps")) return 0;
        const Hdf5Group g(f, "steps", false);
        for (const std::string& name : g.members())
        {
            const bool numeric =
                !name.empty() && name.size() <= 9
             && name.find_first_not_of("0123456789") == std::string::npos;
            if (numeric && std::stoi(name) >= n)
            {
                remove.push_back(name);
            }
        }
    }
    if (remove.empty()) return 0;
    {
        // Damage anywhere in the file stops the edit: the copy would carry
        // it on under a new time stamp
        const Hdf5File f(h5, Hdf5File::Mode::readOnly);
        f.verify();
    }

    // Edited in a copy that replaces the file (AtomicFile.H): a run killed
    // during the edit leaves the file as it was
    const std::string tmp = copyToTemporary(h5);
    {
        Hdf5File f(tmp, Hdf5File::Mode::readWrite);
        {
            Hdf5Group g(f, "steps", false);
            for (const std::string& name : remove) g.remove(name);
        }
        f.close();
    }
    commitFile(tmp, h5);
    return int(remove.size());
}
