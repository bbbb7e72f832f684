// Dense linear complementarity problems solved by pivoting (Lemke's method).
//
// Find z such that  w = M z + q,  w >= 0,  z >= 0,  w . z = 0.
// Used by the exact contact solver (one LCP per coupled island of contacts),
// but independent of the contact model: any dense M and q work.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace collision2d
{
enum class LcpStatus
{
  Solved,            ///< z, w satisfy the LCP (see LcpResult::residual)
  RayTermination,    ///< no pivot row: the LCP is infeasible (or M is outside Lemke's class)
  PivotLimit,        ///< pivot cap reached (cycling or a huge problem)
  NumericalFailure,  ///< pivoting ended but the recomputed solution is not complementary
  InvalidInput       ///< sizes differ, non-finite entries, or a non-positive covering vector
};

struct LcpResult
{
  LcpStatus status = LcpStatus::InvalidInput;
  Eigen::VectorXd z;      ///< the solution (valid when solved())
  Eigen::VectorXd w;      ///< M z + q recomputed from z
  int pivots = 0;         ///< pivots done, including the initial one
  double residual = 0.0;  ///< natural residual max_i |min(z_i, w_i)|, units of q

  bool solved() const { return status == LcpStatus::Solved; }
};

struct LemkeSettings
{
  /// Pivot cap; 0 picks kPivotsPerUnknown * n + kPivotsBase.
  int max_pivots = 0;
  /// Rebuild the tableau from the original data and the current basis every
  /// this many pivots; 0 picks max(n, 32), O(n^2) amortised per pivot.
  int refresh_interval = 0;
  /// Tableau entries below this (relative to the largest entry of the
  /// entering column) are treated as zero: pivoting on them amplifies
  /// round-off without bound.
  double pivot_tolerance = 1e-11;
  /// Ratios (and lexicographic entries) closer than this, relative to the
  /// scale of the right-hand side, count as ties.
  double tie_tolerance = 1e-12;
  /// A solution whose natural residual exceeds this (relative to max|q|) after
  /// the final basis solve is reported as NumericalFailure.
  double accept_tolerance = 1e-8;
};

/// Lemke's complementary pivoting with a covering vector, lexicographic ratio
/// test (no cycling on degenerate problems), and a final solve of the
/// terminal basis with Eigen so that the answer does not carry the
/// tableau's accumulated round-off. Positive semidefinite M (including
/// singular ones, e.g. redundant contacts) is always solved when the LCP is
/// feasible; an infeasible one ends on a ray and is reported, never faked.
///
/// The object keeps its work arrays, so solving many LCPs of similar size
/// with one instance allocates only when a larger problem arrives.
class LemkeSolver
{
public:
  explicit LemkeSolver(const LemkeSettings& settings = LemkeSettings()) : settings_(settings) {}

  /// Covering vector of ones.
  LcpResult solve(const Eigen::MatrixXd& M, const Eigen::VectorXd& q);
  /// Covering vector d (all entries > 0).
  LcpResult solve(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, const Eigen::VectorXd& d);

  const LemkeSettings& settings() const { return settings_; }

  static constexpr int kPivotsPerUnknown = 50;
  static constexpr int kPivotsBase = 100;

private:
  void build_tableau(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, const Eigen::VectorXd& d);
  /// Pivots until z0 leaves the basis; counts them in `pivots`.
  LcpStatus run_pivots(const Eigen::VectorXd& d, int& pivots);
  void pivot(int row, int column);
  void refresh_tableau();
  int initial_row(const Eigen::VectorXd& d);
  int ratio_test(int column);
  int lexicographic_min();
  bool recover_solution(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, LcpResult& result);
  void fill_basis_matrix();

  LemkeSettings settings_;
  int n_ = 0;
  /// [ I | -M | -d | q ] after the pivots so far: columns 0..n-1 are w,
  /// n..2n-1 are z, 2n is the artificial z0, 2n+1 the right-hand side. The
  /// first n columns are the current basis inverse, which the lexicographic
  /// rule reads.
  Eigen::MatrixXd tableau_;
  Eigen::MatrixXd original_;  ///< the tableau before any pivot
  Eigen::RowVectorXd pivot_row_;
  Eigen::VectorXd pivot_column_;  ///< divisor of the ratio and lexicographic tests
  Eigen::MatrixXd basis_;
  Eigen::VectorXd refinement_;  ///< residual of the terminal basis solve
  std::vector<int> basic_;  ///< variable index basic in each row
  std::vector<int> candidates_;  ///< rows tied so far in a ratio test
};

}  // namespace collision2d
