#include "FactorisationEstimate.H"

#include "SolidError.H"

#include <Eigen/OrderingMethods>

#include <vector>


solid::FactorisationEstimate solid::estimateFactorisation
(
    const Eigen::SparseMatrix<double>& A,
    double maxMemory,
    double maxOperations
)
{
    if (A.rows() != A.cols())
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            "estimateFactorisation: the matrix is not square"
        );
    }
    const int n = int(A.rows());
    FactorisationEstimate est;
    est.n = n;
    est.factorEntries = n;
    est.memory = 12.0*n;
    if (n == 0) return est;

    // Symmetric pattern and its AMD ordering: perm(k) is the old index of
    // the k-th unknown eliminated. Eigen's sparse sum keeps every entry of
    // both patterns, whatever the values (no copy of A's pattern needed)
    const Eigen::SparseMatrix<double> S =
        Eigen::SparseMatrix<double>(A.transpose()) + A;
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> perm;
    Eigen::AMDOrdering<int> amd;
    amd(S, perm);
    std::vector<int> newIndex(n);
    for (int k = 0; k < n; ++k) newIndex[perm.indices()(k)] = k;

    // upper[k]: the i < k with S(i, k) != 0, after the ordering
    std::vector<int> start(n + 1, 0);
    for (int j = 0; j < n; ++j)
    {
        for (Eigen::SparseMatrix<double>::InnerIterator it(S, j); it; ++it)
        {
            const int a = newIndex[it.row()], b = newIndex[j];
            if (a < b) ++start[b + 1];
        }
    }
    for (int k = 0; k < n; ++k) start[k + 1] += start[k];
    std::vector<int> upper(start[n]);
    {
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (int j = 0; j < n; ++j)
        {
            for
            (
                Eigen::SparseMatrix<double>::InnerIterator it(S, j);
                it;
                ++it
            )
            {
                const int a = newIndex[it.row()], b = newIndex[j];
                if (a < b) upper[fill[b]++] = a;
            }
        }
    }
    est.matrixEntries = double(S.nonZeros());

    // Elimination tree (with path compression through ancestor)
    std::vector<int> parent(n, -1), ancestor(n, -1);
    for (int k = 0; k < n; ++k)
    {
        for (int p = start[k]; p < start[k + 1]; ++p)
        {
            int i = upper[p];
            while (i != -1 && i < k)
            {
                const int next = ancestor[i];
                ancestor[i] = k;
                if (next == -1) parent[i] = k;
                i = next;
            }
        }
    }

    // Row k of L is the subtree of the etree reached from the entries of
    // row k of A: each node visited adds L(k, i) to column i
    std::vector<int> mark(n, -1);
    std::vector<double> count(n, 0);
    double offDiagonal = 0, operations = 0;
    for (int k = 0; k < n; ++k)
    {
        mark[k] = k;
        for (int p = start[k]; p < start[k + 1]; ++p)
        {
            for (int i = upper[p]; mark[i] != k; i = parent[i])
            {
                mark[i] = k;
                // c_i -> c_i + 1: c + 2c^2 grows by 1 + 2(2c + 1)
                operations += 3 + 4*count[i];
                count[i] += 1;
                offDiagonal += 1;
            }
        }
        est.factorEntries = 2*offDiagonal + n;
        est.memory = 12*est.factorEntries;
        est.operations = operations;
        if (est.memory > maxMemory || est.operations > maxOperations)
        {
            est.complete = k == n - 1;
            return est;
        }
    }
    return est;
}
