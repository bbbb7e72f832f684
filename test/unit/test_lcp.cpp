// Lemke's method on small LCPs whose solutions are known by hand, on
// degenerate and singular (positive semidefinite) ones, on infeasible ones,
// and on random problems built around a planted solution.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "collision2d/lcp.h"

namespace collision2d
{
namespace
{
/// Independent check of the LCP conditions from the returned z alone.
void expect_complementary(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, const LcpResult& result, double tol)
{
  ASSERT_TRUE(result.solved());
  ASSERT_EQ(result.z.size(), q.size());
  const Eigen::VectorXd w = M * result.z + q;
  const double scale = std::max(q.cwiseAbs().maxCoeff(), (M * result.z).cwiseAbs().maxCoeff());
  for (Eigen::Index i = 0; i < q.size(); ++i)
  {
    EXPECT_GE(result.z(i), 0.0) << "z_" << i;
    EXPECT_GE(w(i), -tol * scale) << "w_" << i;
    EXPECT_LE(std::abs(std::min(result.z(i), w(i))), tol * scale) << "complementarity at " << i;
  }
}

Eigen::MatrixXd matrix(int rows, int cols, std::initializer_list<double> values)
{
  Eigen::MatrixXd m(rows, cols);
  auto it = values.begin();
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
      m(i, j) = *it++;
  return m;
}

Eigen::VectorXd vector(std::initializer_list<double> values)
{
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double x : values)
    v(i++) = x;
  return v;
}

constexpr double kTight = 1e-13;

TEST(Lcp, NonNegativeQIsSolvedByZeroWithoutPivots)
{
  LemkeSolver lemke;
  const Eigen::MatrixXd M = matrix(2, 2, {2, 1, 1, 2});
  const Eigen::VectorXd q = vector({0.0, 3.0});
  const LcpResult result = lemke.solve(M, q);
  ASSERT_TRUE(result.solved());
  EXPECT_EQ(result.pivots, 0);
  EXPECT_EQ(result.z, Eigen::VectorXd::Zero(2));
  EXPECT_EQ(result.w, q);
}

TEST(Lcp, EmptyProblemIsSolved)
{
  LemkeSolver lemke;
  EXPECT_TRUE(lemke.solve(Eigen::MatrixXd(0, 0), Eigen::VectorXd(0)).solved());
}

TEST(Lcp, BothActiveMatchesLinearSolve)
{
  // Both z positive: M z = -q, z = (4/3, 7/3).
  LemkeSolver lemke;
  const Eigen::MatrixXd M = matrix(2, 2, {2, 1, 1, 2});
  const Eigen::VectorXd q = vector({-5.0, -6.0});
  const LcpResult result = lemke.solve(M, q);
  expect_complementary(M, q, result, kTight);
  EXPECT_NEAR(result.z(0), 4.0 / 3.0, 1e-14);
  EXPECT_NEAR(result.z(1), 7.0 / 3.0, 1e-14);
}

TEST(Lcp, OneActiveOneSlack)
{
  // z = (1/2, 0): w_1 = 1/2 + 3 = 3.5 > 0.
  LemkeSolver lemke;
  const Eigen::MatrixXd M = matrix(2, 2, {2, 1, 1, 2});
  const Eigen::VectorXd q = vector({-1.0, 3.0});
  const LcpResult result = lemke.solve(M, q);
  expect_complementary(M, q, result, kTight);
  EXPECT_NEAR(result.z(0), 0.5, 1e-15);
  EXPECT_EQ(result.z(1), 0.0);
  EXPECT_NEAR(result.w(1), 3.5, 1e-14);
}

TEST(Lcp, TiedInitialRatiosAreDegenerateButSolved)
{
  // M = I + ones, q = -1: every row ties in the first ratio test.
  // Solution z_i = 1/4 (4 z = 1 per row).
  LemkeSolver lemke;
  const Eigen::MatrixXd M = Eigen::MatrixXd::Identity(3, 3) + Eigen::MatrixXd::Ones(3, 3);
  const Eigen::VectorXd q = -Eigen::VectorXd::Ones(3);
  const LcpResult result = lemke.solve(M, q);
  expect_complementary(M, q, result, kTight);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(result.z(i), 0.25, 1e-15);
}

TEST(Lcp, DegenerateZeroEntriesOfQ)
{
  // Resting rows (q_i = 0) next to an active one: ratio ties at 0. z = (0,
  // 1/2, 0) would leave w = (-1/2, 0, -1/2) < 0, so all three rows activate:
  // M z = (0, 1, 0) with M^-1 = [3 2 1; 2 4 2; 1 2 3] / 4 gives (1/2, 1, 1/2).
  LemkeSolver lemke;
  const Eigen::MatrixXd M = matrix(3, 3, {2, -1, 0, -1, 2, -1, 0, -1, 2});
  const Eigen::VectorXd q = vector({0.0, -1.0, 0.0});
  const LcpResult result = lemke.solve(M, q);
  expect_complementary(M, q, result, kTight);
  EXPECT_NEAR(result.z(0), 0.5, 1e-14);
  EXPECT_NEAR(result.z(1), 1.0, 1e-14);
  EXPECT_NEAR(result.z(2), 0.5, 1e-14);
}

TEST(Lcp, RedundantRowsOfASingularPsdMatrix)
{
  // Two identical rows (two contact points of one face): M = [1 1; 1 1] is
  // singular; any z1 + z2 = 1, z >= 0 solves it.
  LemkeSolver lemke;
  const Eigen::MatrixXd M = Eigen::MatrixXd::Ones(2, 2);
  const Eigen::VectorXd q = vector({-1.0, -1.0});
  const LcpResult result = lemke.solve(M, q);
  expect_complementary(M, q, result, kTight);
  EXPECT_NEAR(result.z.sum(), 1.0, 1e-15);
}

TEST(Lcp, RankTwoPsdMatrixOfABoxOnTwoSupports)
{
  // A rigid bar (mass 1, inertia 1) on supports at x = -1, 0, +1: three rows,
  // rank two (three contacts, two degrees of freedom). Rows J = (1, x_i):
  // M = J J^T. Approach speed 1 everywhere: the bar must stop; the total
  // impulse is 1 (momentum) and the moment sum x_i z_i is 0.
  Eigen::MatrixXd J(3, 2);
  J << 1, -1, 1, 0, 1, 1;
  const Eigen::MatrixXd M = J * J.transpose();
  const Eigen::VectorXd q = -Eigen::VectorXd::Ones(3);
  LemkeSolver lemke;
  const LcpResult result = lemke.solve(M, q);
  expect_complementary(M, q, result, kTight);
  EXPECT_NEAR(result.z.sum(), 1.0, 1e-14);
  EXPECT_NEAR(result.z(2) - result.z(0), 0.0, 1e-14);
}

TEST(Lcp, InfeasibleProblemEndsOnARay)
{
  // w = -z - 1 can never be >= 0.
  LemkeSolver lemke;
  const LcpResult result = lemke.solve(matrix(1, 1, {-1.0}), vector({-1.0}));
  EXPECT_FALSE(result.solved());
  EXPECT_EQ(result.status, LcpStatus::RayTermination);
}

TEST(Lcp, InfeasiblePsdProblemIsReportedNotFaked)
{
  // w1 + w2 = -2 whatever z: a body pinched between two walls it approaches.
  LemkeSolver lemke;
  const Eigen::MatrixXd M = matrix(2, 2, {1, -1, -1, 1});
  const LcpResult result = lemke.solve(M, vector({-1.0, -1.0}));
  EXPECT_EQ(result.status, LcpStatus::RayTermination);
}

TEST(Lcp, InvalidInputIsRejected)
{
  LemkeSolver lemke;
  EXPECT_EQ(lemke.solve(Eigen::MatrixXd::Identity(2, 2), vector({-1.0})).status, LcpStatus::InvalidInput);
  EXPECT_EQ(lemke.solve(matrix(1, 1, {NAN}), vector({-1.0})).status, LcpStatus::InvalidInput);
  EXPECT_EQ(lemke.solve(matrix(1, 1, {1.0}), vector({-1.0}), vector({0.0})).status, LcpStatus::InvalidInput);
}

TEST(Lcp, PivotCapIsReported)
{
  LemkeSettings settings;
  settings.max_pivots = 1;
  LemkeSolver lemke(settings);
  const LcpResult result = lemke.solve(Eigen::MatrixXd::Identity(3, 3) * 2.0, -Eigen::VectorXd::Ones(3));
  EXPECT_EQ(result.status, LcpStatus::PivotLimit);
}

TEST(Lcp, CoveringVectorDoesNotChangeAUniqueSolution)
{
  LemkeSolver lemke;
  const Eigen::MatrixXd M = matrix(2, 2, {2, 1, 1, 2});
  const Eigen::VectorXd q = vector({-5.0, -6.0});
  const LcpResult result = lemke.solve(M, q, vector({0.1, 7.0}));
  expect_complementary(M, q, result, kTight);
  EXPECT_NEAR(result.z(0), 4.0 / 3.0, 1e-14);
  EXPECT_NEAR(result.z(1), 7.0 / 3.0, 1e-14);
}

/// q built from a planted complementary pair (z*, w*): q = w* - M z*.
Eigen::VectorXd planted_q(const Eigen::MatrixXd& M, std::mt19937& rng, Eigen::VectorXd& z_star)
{
  std::uniform_real_distribution<double> value(0.1, 2.0);
  std::bernoulli_distribution active(0.5);
  const Eigen::Index n = M.rows();
  z_star = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd w_star = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i)
    (active(rng) ? z_star(i) : w_star(i)) = value(rng);
  return w_star - M * z_star;
}

TEST(Lcp, RandomPositiveDefiniteRecoversThePlantedSolution)
{
  std::mt19937 rng(42);
  std::normal_distribution<double> gauss(0.0, 1.0);
  LemkeSolver lemke;
  for (int trial = 0; trial < 50; ++trial)
  {
    const int n = 2 + trial % 30;
    const Eigen::MatrixXd A = Eigen::MatrixXd::NullaryExpr(n, n, [&]() { return gauss(rng); });
    const Eigen::MatrixXd M = A * A.transpose() + 1e-2 * Eigen::MatrixXd::Identity(n, n);
    Eigen::VectorXd z_star;
    const Eigen::VectorXd q = planted_q(M, rng, z_star);
    const LcpResult result = lemke.solve(M, q);
    expect_complementary(M, q, result, 1e-12);
    // Positive definite: the solution is unique, so it is the planted one.
    EXPECT_LE((result.z - z_star).cwiseAbs().maxCoeff(), 1e-8 * (1.0 + z_star.cwiseAbs().maxCoeff()))
        << "trial " << trial;
  }
}

TEST(Lcp, RandomSingularPsdIsSolvedToTightResidual)
{
  // Rank-deficient M = A A^T (more rows than degrees of freedom, like
  // redundant contacts); feasible by construction.
  std::mt19937 rng(7);
  std::normal_distribution<double> gauss(0.0, 1.0);
  LemkeSolver lemke;
  for (int trial = 0; trial < 50; ++trial)
  {
    const int n = 3 + trial % 25;
    const int rank = 1 + trial % (n - 1);
    const Eigen::MatrixXd A = Eigen::MatrixXd::NullaryExpr(n, rank, [&]() { return gauss(rng); });
    const Eigen::MatrixXd M = A * A.transpose();
    Eigen::VectorXd z_star;
    const Eigen::VectorXd q = planted_q(M, rng, z_star);
    expect_complementary(M, q, lemke.solve(M, q), 1e-12);
  }
}

TEST(Lcp, FrequentTableauRefreshesGiveTheSameSolution)
{
  // The tableau rebuilt from the basis every 3 pivots must pick the same
  // basis as plain rank-one updates on a positive definite problem.
  std::mt19937 rng(3);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const int n = 60;
  const Eigen::MatrixXd A = Eigen::MatrixXd::NullaryExpr(n, n, [&]() { return gauss(rng); });
  const Eigen::MatrixXd M = A * A.transpose() + 1e-3 * Eigen::MatrixXd::Identity(n, n);
  Eigen::VectorXd z_star;
  const Eigen::VectorXd q = planted_q(M, rng, z_star);
  LemkeSettings settings;
  settings.refresh_interval = 3;
  LemkeSolver refreshing(settings);
  const LcpResult result = refreshing.solve(M, q);
  EXPECT_GT(result.pivots, 10);
  expect_complementary(M, q, result, 1e-12);
  EXPECT_LE((result.z - z_star).cwiseAbs().maxCoeff(), 1e-8 * (1.0 + z_star.cwiseAbs().maxCoeff()));
}

TEST(Lcp, MassRatioMillionColumnKeepsFullAccuracy)
{
  // A 1D column of bodies with masses alternating 1 and 1e6 on the ground,
  // all falling at speed v: contact i sits below body i (row J_i = e_i -
  // e_{i-1}), M = J W J^T, only the ground contact approaches. Every body
  // must stop, so contact i carries v times the mass above it. M itself is
  // rounded (1 + 1e-6 keeps the heavy share to 1e-10), and the ratio
  // amplifies that in z; the speeds w of the problem as given must still be
  // exact to double precision of the impulses' effects.
  const int n = 8;
  const double v = 0.1635;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd inverse_mass(n);
  for (int i = 0; i < n; ++i)
  {
    J(i, i) = 1.0;
    if (i > 0)
      J(i, i - 1) = -1.0;
    inverse_mass(i) = i % 2 == 0 ? 1.0 : 1e-6;
  }
  const Eigen::MatrixXd M = J * inverse_mass.asDiagonal() * J.transpose();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(n);
  q(0) = -v;
  LemkeSolver lemke;
  const LcpResult result = lemke.solve(M, q);
  ASSERT_TRUE(result.solved());
  double above = 0.0;
  for (int i = n - 1; i >= 0; --i)
  {
    above += v / inverse_mass(i);
    EXPECT_NEAR(result.z(i), above, 1e-8 * above) << "contact " << i;
  }
  // Speeds to a few epsilons of the largest impulse effect, v * 4e6 m/s.
  EXPECT_LE(result.w.cwiseAbs().maxCoeff(), 4.0 * std::numeric_limits<double>::epsilon() * v * 4e6);
}

TEST(Lcp, ReusedSolverHandlesShrinkingAndGrowingProblems)
{
  LemkeSolver lemke;
  const Eigen::MatrixXd big = Eigen::MatrixXd::Identity(5, 5) + Eigen::MatrixXd::Ones(5, 5);
  const Eigen::VectorXd q_big = -Eigen::VectorXd::Ones(5);
  expect_complementary(big, q_big, lemke.solve(big, q_big), kTight);
  const Eigen::MatrixXd small = matrix(2, 2, {2, 1, 1, 2});
  const Eigen::VectorXd q_small = vector({-1.0, 3.0});
  expect_complementary(small, q_small, lemke.solve(small, q_small), kTight);
  expect_complementary(big, q_big, lemke.solve(big, q_big), kTight);
}

}  // namespace
}  // namespace collision2d
