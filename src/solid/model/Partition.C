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
