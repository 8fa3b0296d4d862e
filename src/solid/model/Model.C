#include "Model.H"
#include "SolidError.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

solid::Model::Model(Mesh mesh)
:
    mesh_(std::move(mesh))
{
    mesh_.check();
    regionMaterial_.resize(mesh_.regionNames.size());
    owned_ = partition_.elements(mesh_.nElements());
}


void solid::Model::setPartition(Partition partition)
{
    if (initialised_)
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "setPartition: the model is already initialised"
        );
    }
    partition_ = std::move(partition);
    owned_ = partition_.elements(mesh_.nElements());
}


void solid::Model::requireInitialised(const char* what) const
{
    if (!initialised_)
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            std::string("Model::") + what + " called before initialise()"
        );
    }
}


void solid::Model::setMaterial
(
    const std::string& region,
    std::shared_ptr<const Material> material
)
{
    regionMaterial_[mesh_.regionId(region)] = std::move(material);
    initialised_ = false;
}


void solid::Model::fix(const std::string& nodeSet, int comp, TimeFunction f)
{
    for (int n : mesh_.nodeSet(nodeSet)) fixNode(n, comp, f);
}


void solid::Model::fixNode(int node, int comp, TimeFunction f)
{
    if (comp < 0 || comp >= mesh_.dim() || node < 0 || node >= mesh_.nNodes())
    {
        throw SolidError
        (
            SolidError::Kind::parameter, "Dirichlet condition on node "
          + std::to_string(node) + " component " + std::to_string(comp)
          + " is out of range"
        );
    }
    dirichlet_.push_back({node*mesh_.dim() + comp, f});
    initialised_ = false;
}


void solid::Model::add(std::shared_ptr<Contribution> c)
{
    contributions_.push_back(std::move(c));
}


void solid::Model::initialise()
{
    for (std::size_t r = 0; r < regionMaterial_.size(); ++r)
    {
        if (!regionMaterial_[r])
        {
            int n = 0;
            for (int reg : mesh_.region) n += (reg == int(r));
            throw SolidError
            (
                SolidError::Kind::parameter,
                "region '" + mesh_.regionNames[r] + "' ("
              + std::to_string(n) + " elements) has no material"
            );
        }
    }
    const int ne = mesh_.nElements();
    geometry_.resize(ne);
    multiplier_.assign(ne, -1);
    int nm = 0;
    std::vector<int> pointSizes(ne), elemSizes(ne);
    lumpedMass_ = Eigen::VectorXd::Zero(nDisplacementDofs());
    const int dim = mesh_.dim();
    for (int e = 0; e < ne; ++e)
    {
        geometry_[e].build(mesh_, e);
        const Material& m = material(e);
        if (m.volumetric().hasInverse()) multiplier_[e] = nm++;
        pointSizes[e] = int(geometry_[e].w.size())*m.isochoric().nHistory();
        elemSizes[e] = m.volumetric().nHistory()
           *(pointVolumetric_ ? int(geometry_[e].w.size()) : 1);
        const int* en = mesh_.element(e);
        for (int a = 0; a < mesh_.nen(); ++a)
        {
            for (int i = 0; i < dim; ++i)
            {
                lumpedMass_(en[a]*dim + i) +=
                    m.rho0()*geometry_[e].lumpedMass(a);
            }
        }
    }
    pointState_.resize(pointSizes);
    elementState_.resize(elemSizes);
    for (int e = 0; e < ne; ++e)
    {
        const Material& m = material(e);
        const int nh = m.isochoric().nHistory();
        for (std::size_t q = 0; q < geometry_[e].w.size(); ++q)
        {
            m.isochoric().initHistory(pointState_.old(e) + q*nh);
        }
        const int nv = m.volumetric().nHistory();
        for (int q = 0; q*nv < elementState_.size(e); ++q)
        {
            m.volumetric().initHistory(elementState_.old(e) + q*nv);
        }
    }
    pointState_.revert();
    elementState_.revert();
    ownedPointRanges_ = pointState_.ranges(owned_);
    ownedElementRanges_ = elementState_.ranges(owned_);

    u = Eigen::VectorXd::Zero(nDisplacementDofs());
    v = Eigen::VectorXd::Zero(nDisplacementDofs());
    pressure = Eigen::VectorXd::Zero(nm);
    freeIndex_.assign(nUnknowns(), 0);
    for (const auto& d : dirichlet_) freeIndex_[d.dof] = -1;
    nFree_ = 0;
    for (auto& f : freeIndex_)
    {
        if (f == 0) f = nFree_++;
    }
    initialised_ = true;
    pattern_ = TangentPattern();
    applyDirichlet(u, time);
}


void solid::Model::buildPattern()
{
    const int dim = mesh_.dim(), nen = mesh_.nen(), nd = nen*dim;
    const int nu = nDisplacementDofs();
    const int ne = mesh_.nElements();
    TangentPattern& tp = pattern_;
    tp.blockSize = nd*nd + 2*nd + 1;
    // Same (row, col) list as the element loop of assemble(), reduced
    std::vector<int> row(std::size_t(ne)*tp.blockSize, -1);
    std::vector<int> col(row.size(), -1);
    Triplets t;
    t.reserve(row.size() + tp.extra.size());
    std::vector<int> dofs(nd);
    for (int e = 0; e < ne; ++e)
    {
        const int* en = mesh_.element(e);
        for (int b = 0; b < nen; ++b)
            for (int i = 0; i < dim; ++i) dofs[b*dim + i] = en[b]*dim + i;
        int* r = row.data() + std::size_t(e)*tp.blockSize;
        int* c = col.data() + std::size_t(e)*tp.blockSize;
        int k = 0;
        for (int i = 0; i < nd; ++i)
            for (int j = 0; j < nd; ++j, ++k)
            {
                r[k] = freeIndex_[dofs[i]];
                c[k] = freeIndex_[dofs[j]];
            }
        if (multiplier_[e] >= 0)
        {
            const int pm = freeIndex_[nu + multiplier_[e]];
            for (int i = 0; i < nd; ++i, k += 2)
            {
                r[k] = freeIndex_[dofs[i]];
                c[k] = pm;
                r[k + 1] = pm;
                c[k + 1] = freeIndex_[dofs[i]];
            }
            r[k] = pm;
            c[k] = pm;
        }
    }
    for (std::size_t k = 0; k < row.size(); ++k)
    {
        if (row[k] >= 0 && col[k] >= 0) t.emplace_back(row[k], col[k], 0.0);
    }
    for (const auto& rc : tp.extra) t.emplace_back(rc.first, rc.second, 0.0);
    tp.K.resize(nFree_, nFree_);
    tp.K.setFromTriplets(t.begin(), t.end());
    tp.K.makeCompressed();
    tp.slot.assign(row.size(), -1);
    const int* outer = tp.K.outerIndexPtr();
    const int* inner = tp.K.innerIndexPtr();
    for (std::size_t k = 0; k < row.size(); ++k)
    {
        if (row[k] < 0 || col[k] < 0) continue;
        const int* p = std::lower_bound
        (
            inner + outer[col[k]], inner + outer[col[k] + 1], row[k]
        );
        tp.slot[k] = int(p - inner);
    }
    tp.built = true;
}


const Eigen::SparseMatrix<double>& solid::Model::tangentPattern()
{
    requireInitialised("tangentPattern");
    if (!pattern_.built) buildPattern();
    return pattern_.K;
}


bool solid::Model::addToPattern
(
    const Triplets& t,
    Eigen::SparseMatrix<double>& K
)
{
    const int* outer = K.outerIndexPtr();
    const int* inner = K.innerIndexPtr();
    double* value = K.valuePtr();
    bool inside = true;
    for (const auto& tr : t)
    {
        const int r = freeIndex_[tr.row()], c = freeIndex_[tr.col()];
        if (r < 0 || c < 0) continue;
        const int* end = inner + outer[c + 1];
        const int* p = std::lower_bound(inner + outer[c], end, r);
        if (p != end && *p == r)
        {
            value[p - inner] += tr.value();
        }
        else
        {
            pattern_.extra.emplace_back(r, c);
            inside = false;
        }
    }
    return inside;
}


void solid::Model::applyDirichlet(Eigen::VectorXd& x, double t) const
{
    for (const auto& d : dirichlet_) x(d.dof) = d.value ? d.value(t) : 0.0;
}


std::vector<int> solid::Model::prescribedDofs() const
{
    std::set<int> s;
    for (const auto& d : dirichlet_) s.insert(d.dof);
    return std::vector<int>(s.begin(), s.end());
}


Eigen::VectorXd solid::Model::elementDisplacement
(
    int e,
    const Eigen::VectorXd& x
) const
{
    const int dim = mesh_.dim(), nen = mesh_.nen();
    Eigen::VectorXd ue(nen*dim);
    const int* en = mesh_.element(e);
    for (int a = 0; a < nen; ++a)
        for (int i = 0; i < dim; ++i) ue(a*dim + i) = x(en[a]*dim + i);
    return ue;
}


void solid::Model::externalForce
(
    const Eigen::VectorXd& x,
    double t,
    Eigen::VectorXd& fext
) const
{
    fext = Eigen::VectorXd::Zero(nDisplacementDofs());
    for (const auto& c : contributions_) c->addForce(*this, x, t, fext, nullptr);
}


void solid::Model::assemble
(
    const Eigen::VectorXd& x,
    const Eigen::VectorXd& p,
    double t,
    double dt,
    bool tangent,
    Assembly& a,
    bool combine
)
{
    requireInitialised("assemble");
    if (tangent && !partition_.serial())
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "Model::assemble: the tangent of a model shared over "
          + std::to_string(partition_.nParts()) + " parts (one part only)"
        );
    }
    const int dim = mesh_.dim(), nen = mesh_.nen(), nd = nen*dim;
    const int nu = nDisplacementDofs();
    a.fint = Eigen::VectorXd::Zero(nu);
    a.constraint = Eigen::VectorXd::Zero(nMultipliers());
    a.contributionK.clear();
    a.energy = 0;
    a.dissipated = 0;
    a.shockHeat = 0;
    a.viscousHeat = 0;
    a.temperatureRiseMax = 0;
    a.stableDt = std::numeric_limits<double>::infinity();
    double* Kv = nullptr;
    if (tangent)
    {
        if (!pattern_.built) buildPattern();
        const Eigen::SparseMatrix<double>& P = pattern_.K;
        if
        (
            a.K.nonZeros() != P.nonZeros() || a.K.rows() != P.rows()
         || !std::equal
            (
                P.outerIndexPtr(), P.outerIndexPtr() + P.outerSize() + 1,
                a.K.outerIndexPtr()
            )
        )
        {
            a.K = P;
        }
        Kv = a.K.valuePtr();
        std::fill(Kv, Kv + a.K.nonZeros(), 0.0);
    }
    ElementOutput out;
    std::vector<int> dofs(nd);
    Eigen::VectorXd ue(nd);
    for (const int e : owned_)
    {
        const int* en = mesh_.element(e);
        for (int b = 0; b < nen; ++b)
        {
            for (int i = 0; i < dim; ++i)
            {
                dofs[b*dim + i] = en[b]*dim + i;
                ue(b*dim + i) = x(en[b]*dim + i);
            }
        }
        const int m = usesMultiplier(e) ? multiplier_[e] : -1;
        MixedElement::evaluate
        (
            mesh_, e, geometry_[e], material(e), ue,
            m >= 0, m >= 0 ? p(m) : 0.0, dt,
            pointState_.old(e), pointState_.current(e),
            elementState_.old(e), elementState_.current(e),
            tangent, out, cornerCheck_, pointVolumetric_
        );
        for (int i = 0; i < nd; ++i) a.fint(dofs[i]) += out.f(i);
        a.energy += out.energy;
        a.dissipated += out.dissipated;
        a.shockHeat += out.shockHeat;
        a.viscousHeat += out.viscousHeat;
        a.temperatureRiseMax =
            std::max(a.temperatureRiseMax, out.temperatureRise);
        if (out.c2 > 0)
        {
            // Abaqus/Explicit: dt = L/c_d (sqrt(1 + zeta^2) - zeta)
            const double cd = std::sqrt(out.c2);
            a.stableDt = std::min
            (
                a.stableDt,
                out.length/cd*(std::sqrt(1 + out.zeta*out.zeta) - out.zeta)
            );
        }
        const VolumetricLaw& vol = material(e).volumetric();
        if (m >= 0)
        {
            a.constraint(m) = -(out.v - geometry_[e].V*vol.dilatation(p(m)));
        }
        if (tangent)
        {
            // Scatter in the order of the former triplet list (element by
            // element), so every entry sums its terms in the same order
            const int* s =
                pattern_.slot.data() + std::size_t(e)*pattern_.blockSize;
            int k = 0;
            for (int i = 0; i < nd; ++i)
                for (int j = 0; j < nd; ++j, ++k)
                    if (s[k] >= 0) Kv[s[k]] += out.K(i, j);
            if (m >= 0)
            {
                for (int i = 0; i < nd; ++i, k += 2)
                {
                    if (s[k] >= 0) Kv[s[k]] += -out.g(i);
                    if (s[k + 1] >= 0) Kv[s[k + 1]] += -out.g(i);
                }
                if (s[k] >= 0)
                {
                    Kv[s[k]] += geometry_[e].V*vol.dilatationDerivative(p(m));
                }
            }
        }
    }
    if (combine) combineParts(a);
    a.fext = Eigen::VectorXd::Zero(nu);
    for (const auto& c : contributions_)
    {
        c->addForce
        (
            *this, x, t, a.fext, tangent ? &a.contributionK : nullptr
        );
    }
    if (tangent && !addToPattern(a.contributionK, a.K))
    {
        // A contribution coupled dofs outside the element pattern: extend
        // the pattern once and assemble again
        buildPattern();
        assemble(x, p, t, dt, tangent, a, combine);
    }
}


void solid::Model::combineParts(Assembly& a, Eigen::VectorXd* more) const
{
    if (partition_.serial()) return;
    const std::size_t nf = a.fint.size(), nc = a.constraint.size();
    const std::size_t nm = more ? more->size() : 0;
    const std::size_t nSum = nf + nc + nm + 4;
    std::vector<double> x(nSum + 2);
    double* p = x.data();
    p = std::copy(a.fint.data(), a.fint.data() + nf, p);
    p = std::copy(a.constraint.data(), a.constraint.data() + nc, p);
    if (more) p = std::copy(more->data(), more->data() + nm, p);
    *p++ = a.energy;
    *p++ = a.dissipated;
    *p++ = a.shockHeat;
    *p++ = a.viscousHeat;
    *p++ = a.stableDt;
    *p++ = a.temperatureRiseMax;
    partition_.combine(x.data(), nSum, 1, 1);
    const double* q = x.data();
    std::copy(q, q + nf, a.fint.data());
    q += nf;
    std::copy(q, q + nc, a.constraint.data());
    q += nc;
    if (more)
    {
        std::copy(q, q + nm, more->data());
        q += nm;
    }
    a.energy = *q++;
    a.dissipated = *q++;
    a.shockHeat = *q++;
    a.viscousHeat = *q++;
    a.stableDt = *q++;
    a.temperatureRiseMax = *q++;
}


void solid::Model::shareStates(const std::vector<int>& elements)
{
    if (partition_.serial()) return;
    const int ne = mesh_.nElements(), part = partition_.part();
    std::size_t n = 0;
    for (const int e : elements)
    {
        n += pointState_.size(e) + elementState_.size(e);
    }
    // Owners' blocks, zeros elsewhere: the sum is the owner's value
    std::vector<double> x(n, 0.0);
    std::size_t k = 0;
    for (const int e : elements)
    {
        const bool mine = partition_.owner(e, ne) == part;
        for (StateArray* s : {&pointState_, &elementState_})
        {
            const double* o = s->old(e);
            for (int i = 0; i < s->size(e); ++i, ++k)
            {
                if (mine) x[k] = o[i];
            }
        }
    }
    partition_.combine(x.data(), n);
    k = 0;
    for (const int e : elements)
    {
        for (StateArray* s : {&pointState_, &elementState_})
        {
            double* o = s->old(e);
            double* c = s->current(e);
            for (int i = 0; i < s->size(e); ++i, ++k)
            {
                o[i] = x[k];
                c[i] = x[k];
            }
        }
    }
}


void solid::Model::shareStates()
{
    if (partition_.serial()) return;
    std::vector<int> all(mesh_.nElements());
    for (int e = 0; e < mesh_.nElements(); ++e) all[e] = e;
    shareStates(all);
}


void solid::Model::setPointVolumetric(bool on)
{
    if (initialised_)
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "setPointVolumetric: the model is already initialised"
        );
    }
    pointVolumetric_ = on;
}


solid::ElementOutput solid::Model::evaluateElement(int e, double dt)
{
    requireInitialised("evaluateElement");
    ElementOutput out;
    const int m = usesMultiplier(e) ? multiplier_[e] : -1;
    // Evaluate from the committed history without touching it
    std::vector<double> pn(pointState_.size(e)), en(elementState_.size(e));
    MixedElement::evaluate
    (
        mesh_, e, geometry_[e], material(e), elementDisplacement(e, u),
        m >= 0, m >= 0 ? pressure(m) : 0.0, dt, pointState_.old(e), pn.data(),
        elementState_.old(e), en.data(), false, out, false, pointVolumetric_
    );
    return out;
}


void solid::Model::commit()
{
    pointState_.commit(ownedPointRanges_);
    elementState_.commit(ownedElementRanges_);
    for (const auto& c : contributions_) c->commit(*this, u, time);
}


void solid::Model::revert()
{
    pointState_.revert(ownedPointRanges_);
    elementState_.revert(ownedElementRanges_);
    for (const auto& c : contributions_) c->revert();
}
