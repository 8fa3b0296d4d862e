#include "Partition.H"
#include "SolidError.H"

#include <algorithm>
#include <string>

solid::Partition::Partition(int part, int nParts, AllGather allGather)
:
    part_(part),
    nParts_(nParts),
    allGather_(std::move(allGather))
{
    if (nParts < 1 || part < 0 || part >= nParts)
    {
        throw SolidError
        (
            SolidError::Kind::parameter, "partition: part "
          + std::to_string(part) + " of " + std::to_string(nParts)
          + " parts (valid: 0 <= part < parts, parts >= 1)"
        );
    }
    if (nParts > 1 && !allGather_)
    {
        throw SolidError
        (
            SolidError::Kind::parameter, "partition: "
          + std::to_string(nParts) + " parts without an exchange"
        );
    }
}


void solid::Partition::combine
(
    double* x,
    std::size_t nSum,
    std::size_t nMin,
    std::size_t nMax
) const
{
    if (nParts_ == 1) return;
    const std::size_t n = nSum + nMin + nMax;
    buffer_.resize(n*nParts_);
    allGather_(x, n, buffer_.data());
    const double* all = buffer_.data();
    std::copy(all, all + n, x);
    for (int r = 1; r < nParts_; ++r)
    {
        const double* y = all + std::size_t(r)*n;
        for (std::size_t i = 0; i < nSum; ++i) x[i] += y[i];
        for (std::size_t i = nSum; i < nSum + nMin; ++i)
        {
            x[i] = std::min(x[i], y[i]);
        }
        for (std::size_t i = nSum + nMin; i < n; ++i)
        {
            x[i] = std::max(x[i], y[i]);
        }
    }
}


namespace
{

//- The part whose block of n items (floor(n p/nParts) onwards) holds i
int blockOwner(int i, int n, int nParts)
{
    int p = nParts - 1;
    while (static_cast<long long>(n)*p/nParts > i) --p;
    return p;
}

} // namespace


void solid::Partition::shareOut(const std::vector<bool>& marked)
{
    const int n = int(marked.size());
    const int nMarked = int(std::count(marked.begin(), marked.end(), true));
    sharedOut_ = true;
    owner_.assign(n, 0);
    // The k-th marked element (and the k-th of the others) as the k-th
    // element of the default blocks of its class
    int kMarked = 0, kOther = 0;
    for (int e = 0; e < n; ++e)
    {
        owner_[e] =
            marked[e]
          ? blockOwner(kMarked++, nMarked, nParts_)
          : blockOwner(kOther++, n - nMarked, nParts_);
    }
}


int solid::Partition::owner(int e, int n) const
{
    if (e < 0 || e >= n)
    {
        throw SolidError
        (
            SolidError::Kind::parameter, "partition: element "
          + std::to_string(e) + " of " + std::to_string(n)
          + " (valid: 0 <= element < elements)"
        );
    }
    if (sharedOut_)
    {
        if (n != int(owner_.size()))
        {
            throw SolidError
            (
                SolidError::Kind::parameter, "partition: "
              + std::to_string(n) + " elements asked for, "
              + std::to_string(owner_.size()) + " shared out"
            );
        }
        return owner_[e];
    }
    // The last part whose block starts at or before e
    return blockOwner(e, n, nParts_);
}


std::vector<int> solid::Partition::elements(int n) const
{
    std::vector<int> mine;
    if (!sharedOut_)
    {
        for (int e = begin(n); e < end(n); ++e) mine.push_back(e);
        return mine;
    }
    if (n != int(owner_.size()))
    {
        owner(0, n);    // its error (element or count)
    }
    for (int e = 0; e < n; ++e)
    {
        if (owner_[e] == part_) mine.push_back(e);
    }
    return mine;
}


void solid::Partition::combine(PackedValues& values) const
{
    if (nParts_ == 1) return;
    const std::size_t n = values.values_.size();
    buffer_.resize(n*nParts_);
    allGather_(values.values_.data(), n, buffer_.data());
    const double* all = buffer_.data();
    double* x = values.values_.data();
    for (const PackedValues::Block& b : values.blocks_)
    {
        const std::size_t i0 = b.begin, i1 = b.begin + b.size;
        if (b.kind >= 0)
        {
            // The owner's values (a part beyond the last: SolidError at
            // packing would be too early, the parts are known here)
            if (b.kind >= nParts_)
            {
                throw SolidError
                (
                    SolidError::Kind::parameter, "partition: values "
                    "owned by part " + std::to_string(b.kind) + " of "
                  + std::to_string(nParts_) + " parts"
                );
            }
            const double* y = all + std::size_t(b.kind)*n;
            std::copy(y + i0, y + i1, x + i0);
            continue;
        }
        std::copy(all + i0, all + i1, x + i0);
        for (int r = 1; r < nParts_; ++r)
        {
            const double* y = all + std::size_t(r)*n;
            if (b.kind == PackedValues::sumKind)
            {
                for (std::size_t i = i0; i < i1; ++i) x[i] += y[i];
            }
            else if (b.kind == PackedValues::minKind)
            {
                for (std::size_t i = i0; i < i1; ++i)
                {
                    x[i] = std::min(x[i], y[i]);
                }
            }
            else
            {
                for (std::size_t i = i0; i < i1; ++i)
                {
                    x[i] = std::max(x[i], y[i]);
                }
            }
        }
    }
}


std::size_t solid::PackedValues::add
(
    int kind,
    const double* x,
    std::size_t n
)
{
    const std::size_t begin = values_.size();
    if (x)
    {
        values_.insert(values_.end(), x, x + n);
    }
    else
    {
        values_.resize(begin + n, 0.0);
    }
    // Consecutive values of one kind: one block
    if
    (
        !blocks_.empty() && blocks_.back().kind == kind
     && blocks_.back().begin + blocks_.back().size == begin
    )
    {
        blocks_.back().size += n;
    }
    else if (n)
    {
        blocks_.push_back({begin, n, kind});
    }
    return begin;
}


std::size_t solid::PackedValues::owned
(
    int owner,
    const double* x,
    std::size_t n
)
{
    if (owner < 0)
    {
        throw SolidError
        (
            SolidError::Kind::parameter, "packed values: owner part "
          + std::to_string(owner) + " (valid: >= 0)"
        );
    }
    return add(owner, x, n);
}
