#include "ModelSnapshot.H"
#include "Model.H"
#include "SolidError.H"

namespace
{

std::vector<double> copy(const Eigen::VectorXd& x)
{
    return std::vector<double>(x.data(), x.data() + x.size());
}

Eigen::VectorXd copy(const std::vector<double>& x)
{
    return Eigen::Map<const Eigen::VectorXd>(x.data(), x.size());
}

} // namespace


const char* solid::ModelSnapshot::name(Part p)
{
    static const char* const names[nParts] =
    {
        "u", "v", "pressure", "pointState", "elementState"
    };
    return names[p];
}


std::array<std::size_t, solid::ModelSnapshot::nParts>
solid::ModelSnapshot::sizes(const Model& model)
{
    return
    {
        std::size_t(model.u.size()),
        std::size_t(model.v.size()),
        std::size_t(model.pressure.size()),
        model.pointState().oldData().size(),
        model.elementState().oldData().size()
    };
}


solid::ModelSnapshot::ModelSnapshot(const Model& model)
:
    parts_
    {
        copy(model.u),
        copy(model.v),
        copy(model.pressure),
        model.pointState().oldData(),
        model.elementState().oldData()
    },
    time_(model.time)
{}


void solid::ModelSnapshot::restore(Model& model) const
{
    const auto expected = sizes(model);
    for (int p = 0; p < nParts; ++p)
    {
        if (parts_[p].size() != expected[p])
        {
            throw SolidError
            (
                SolidError::Kind::io, "model state: '"
              + std::string(name(Part(p))) + "' has "
              + std::to_string(parts_[p].size()) + " values, the model "
              + std::to_string(expected[p])
              + " (another mesh or materials?)"
            );
        }
    }
    model.u = copy(parts_[u]);
    model.v = copy(parts_[v]);
    model.pressure = copy(parts_[pressure]);
    model.time = time_;
    StateArray& ps = model.pointState();
    StateArray& es = model.elementState();
    ps.oldData() = parts_[pointState];
    ps.currentData() = parts_[pointState];
    es.oldData() = parts_[elementState];
    es.currentData() = parts_[elementState];
}
