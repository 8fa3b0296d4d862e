#include "ModelSnapshot.H"
#include "Model.H"
#include "SolidError.H"

#include <algorithm>

namespace
{

void copy(const Eigen::VectorXd& x, std::vector<double>& y)
{
    y.assign(x.data(), x.data() + x.size());
}

Eigen::VectorXd copy(const std::vector<double>& x)
{
    return Eigen::Map<const Eigen::VectorXd>(x.data(), x.size());
}

using Ranges = std::vector<solid::StateArray::Range>;

std::size_t count(const Ranges& r)
{
    std::size_t n = 0;
    for (const auto& x : r) n += x.second - x.first;
    return n;
}

//- The values of x in ranges r, packed in their order, into y
void gather(const std::vector<double>& x, const Ranges& r,
    std::vector<double>& y)
{
    y.resize(count(r));
    auto out = y.begin();
    for (const auto& i : r)
    {
        out = std::copy(x.begin() + i.first, x.begin() + i.second, out);
    }
}

//- The inverse: y's values into the ranges r of x (and of z)
void scatter(const std::vector<double>& y, const Ranges& r,
    std::vector<double>& x, std::vector<double>& z)
{
    auto in = y.begin();
    for (const auto& i : r)
    {
        const auto next = in + (i.second - i.first);
        std::copy(in, next, x.begin() + i.first);
        std::copy(in, next, z.begin() + i.first);
        in = next;
    }
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


solid::ModelSnapshot::ModelSnapshot
(
    const Model& model,
    const Histories histories
)
{
    take(model, histories);
}


void solid::ModelSnapshot::take
(
    const Model& model,
    const Histories histories
)
{
    copy(model.u, parts_[u]);
    copy(model.v, parts_[v]);
    copy(model.pressure, parts_[pressure]);
    if (histories == Histories::owned)
    {
        gather
        (
            model.pointState().oldData(), model.ownedPointRanges(),
            parts_[pointState]
        );
        gather
        (
            model.elementState().oldData(), model.ownedElementRanges(),
            parts_[elementState]
        );
    }
    else
    {
        parts_[pointState] = model.pointState().oldData();
        parts_[elementState] = model.elementState().oldData();
    }
    time_ = model.time;
    histories_ = histories;
}


void solid::ModelSnapshot::restore(Model& model) const
{
    auto expected = sizes(model);
    if (histories_ == Histories::owned)
    {
        expected[pointState] = count(model.ownedPointRanges());
        expected[elementState] = count(model.ownedElementRanges());
    }
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
    if (histories_ == Histories::owned)
    {
        scatter
        (
            parts_[pointState], model.ownedPointRanges(), ps.oldData(),
            ps.currentData()
        );
        scatter
        (
            parts_[elementState], model.ownedElementRanges(),
            es.oldData(), es.currentData()
        );
        return;
    }
    ps.oldData() = parts_[pointState];
    ps.currentData() = parts_[pointState];
    es.oldData() = parts_[elementState];
    es.currentData() = parts_[elementState];
}
