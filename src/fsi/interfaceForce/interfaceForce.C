#include "interfaceForce.H"

#include <stdexcept>

Foam::interfaceForce::interfaceForce(const std::vector<int>& nodes, int dim)
:
    nodes_(nodes),
    dim_(dim),
    force_(nodes.size()*dim, 0.0)
{}


void Foam::interfaceForce::set(const std::vector<double>& f)
{
    if (f.size() != force_.size())
    {
        throw std::logic_error("interfaceForce: wrong number of dofs");
    }
    force_ = f;
}


void Foam::interfaceForce::addForce
(
    const solid::Model&,
    const Eigen::VectorXd&,
    double,
    Eigen::VectorXd& f,
    solid::Triplets*
) const
{
    for (std::size_t i = 0; i < nodes_.size(); ++i)
    {
        for (int d = 0; d < dim_; ++d)
        {
            f(dim_*nodes_[i] + d) += force_[dim_*i + d];
        }
    }
}
