// The cost of a sparse factorisation estimated from the pattern
// (FactorisationEstimate, issue 19 sp08): exact on matrices whose factor
// is known (tridiagonal: no fill; dense: full), the factor's non-zeros
// equal to those of Eigen's LDL^T with the same AMD ordering on a 2D
// Laplacian and on a model's tangent, growing from an axisymmetric to a
// 3D mesh, and the count stopped above a limit.
#include "FactorisationEstimate.H"
#include "Model.H"
#include "SolidError.H"
#include "SolidTestUtils.H"

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

using namespace solid;

namespace
{

using Sparse = Eigen::SparseMatrix<double>;

Sparse fromTriplets(int n, const std::vector<Eigen::Triplet<double>>& t)
{
    Sparse A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    A.makeCompressed();
    return A;
}

// 5-point Laplacian of an m x m grid, symmetric positive definite
Sparse laplacian2D(int m)
{
    std::vector<Eigen::Triplet<double>> t;
    auto id = [m](int i, int j) { return i*m + j; };
    for (int i = 0; i < m; ++i)
    {
        for (int j = 0; j < m; ++j)
        {
            t.emplace_back(id(i, j), id(i, j), 4.0);
            if (i > 0) t.emplace_back(id(i, j), id(i - 1, j), -1.0);
            if (i < m - 1) t.emplace_back(id(i, j), id(i + 1, j), -1.0);
            if (j > 0) t.emplace_back(id(i, j), id(i, j - 1), -1.0);
            if (j < m - 1) t.emplace_back(id(i, j), id(i, j + 1), -1.0);
        }
    }
    return fromTriplets(m*m, t);
}

// The strictly lower non-zeros of Eigen's LDL^T (AMD ordering) of A
double ldltOffDiagonal(const Sparse& A)
{
    Eigen::SimplicialLDLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int>> f;
    f.analyzePattern(A);
    f.factorize(A);
    EXPECT_EQ(f.info(), Eigen::Success);
    return double(Sparse(f.matrixL()).nonZeros()) - A.rows();
}

} // namespace


TEST(FactorisationEstimate, TridiagonalHasNoFill)
{
    const int n = 100;
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i)
    {
        t.emplace_back(i, i, 2.0);
        if (i > 0) t.emplace_back(i, i - 1, -1.0);
        if (i < n - 1) t.emplace_back(i, i + 1, -1.0);
    }
    const FactorisationEstimate e = estimateFactorisation(fromTriplets(n, t));
    EXPECT_TRUE(e.complete);
    EXPECT_EQ(e.n, n);
    // c_j = 1 for every column but the last: n - 1 entries below the
    // diagonal, 3 operations each
    EXPECT_DOUBLE_EQ(e.factorEntries, 2*(n - 1) + n);
    EXPECT_DOUBLE_EQ(e.operations, 3.0*(n - 1));
    EXPECT_DOUBLE_EQ(e.memory, 12*e.factorEntries);
}


TEST(FactorisationEstimate, DenseIsFull)
{
    const int n = 40;
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) t.emplace_back(i, j, i == j ? n : 1.0);
    const FactorisationEstimate e = estimateFactorisation(fromTriplets(n, t));
    double ops = 0;
    for (int c = 0; c < n; ++c) ops += c + 2.0*c*c;
    EXPECT_DOUBLE_EQ(e.factorEntries, double(n)*n);
    EXPECT_DOUBLE_EQ(e.operations, ops);
}


TEST(FactorisationEstimate, FactorEntriesAreThoseOfEigensLdlt)
{
    for (int m : {5, 20, 60})
    {
        const Sparse A = laplacian2D(m);
        const FactorisationEstimate e = estimateFactorisation(A);
        EXPECT_TRUE(e.complete);
        EXPECT_DOUBLE_EQ((e.factorEntries - A.rows())/2, ldltOffDiagonal(A))
            << "grid " << m << " x " << m;
    }
    // A non-symmetric pattern is estimated as that of A + A^T
    std::vector<Eigen::Triplet<double>> t{{0, 0, 1}, {1, 1, 1}, {2, 2, 1},
                                          {0, 2, 1}};
    EXPECT_DOUBLE_EQ(estimateFactorisation(fromTriplets(3, t)).factorEntries,
                     5);
}


TEST(FactorisationEstimate, ModelTangentAndTheCostOf3D)
{
    // The tangent of a compressible (d0 > 0: quasi-definite, LDL^T)
    // block: the estimate's factor is Eigen's
    Model axi(Mesh::rectangle(12, 8, 0, 1e-5, 0, 1e-5));
    axi.setMaterial("solid", solidTest::material(13.33, 0.01, {}));
    axi.fix("bottom", 1);
    axi.fix("left", 0);
    axi.initialise();
    const Sparse& K = axi.tangentPattern();
    EXPECT_EQ(K.rows(), axi.nFree());
    const FactorisationEstimate ea = estimateFactorisation(K);
    Sparse Kspd = K;
    for (int j = 0; j < Kspd.outerSize(); ++j)
        for (Sparse::InnerIterator it(Kspd, j); it; ++it)
            it.valueRef() = it.row() == it.col() ? 1e3 : 1e-3;
    EXPECT_DOUBLE_EQ((ea.factorEntries - K.rows())/2, ldltOffDiagonal(Kspd));

    // The same number of elements in 3D costs far more per unknown
    Model box(Mesh::box(10, 10, 10, Vec3(0, 0, 0), Vec3(1e-5, 1e-5, 1e-5)));
    box.setMaterial("solid", solidTest::material(13.33, 0.01, {}));
    box.fix("zmin", 2);
    box.initialise();
    const FactorisationEstimate e3 = estimateFactorisation(box.tangentPattern());
    EXPECT_GT(e3.operations/e3.n, 20*ea.operations/ea.n);

    // Stopped above a limit: lower bounds beyond it
    const FactorisationEstimate cut =
        estimateFactorisation(box.tangentPattern(), 1e300, e3.operations/10);
    EXPECT_FALSE(cut.complete);
    EXPECT_GT(cut.operations, e3.operations/10);
    EXPECT_LE(cut.operations, e3.operations);
    const FactorisationEstimate cutMemory =
        estimateFactorisation(box.tangentPattern(), e3.memory/10);
    EXPECT_FALSE(cutMemory.complete);
    EXPECT_GT(cutMemory.memory, e3.memory/10);
}


TEST(FactorisationEstimate, PatternBeforeInitialiseIsAnError)
{
    Model m(Mesh::rectangle(2, 2, 0, 1e-5, 0, 1e-5));
    EXPECT_THROW(m.tangentPattern(), SolidError);
    EXPECT_THROW
    (
        estimateFactorisation(Sparse(3, 2)), SolidError
    );
}
