// Lemke's complementary pivoting on a dense tableau (see lcp.h for the
// contract). The tableau is only used to choose the pivots; the reported
// solution comes from solving the terminal basis against the original data.
#include "collision2d/lcp.h"

#include "eigen_blocking.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collision2d
{
namespace
{
/// Rebuild the tableau from the original data after this many pivots (at
/// least): round-off accumulates with every rank-one update, and a fresh
/// B^-1 [I | -M | -d | q] costs O(n^3), i.e. O(n^2) amortised per pivot when
/// done once every n pivots.
constexpr int kMinRefreshInterval = 32;

/// Iterative refinement steps on the terminal basis; each gains about
/// -log10(cond * eps) digits, so a few reach double precision.
constexpr int kRefinementSteps = 4;

/// Reciprocal condition number below which the terminal basis is not
/// trusted. A 1e6 mass ratio gives about 1e-9.
constexpr double kMinBasisRcond = 1e-14;

bool all_finite(const Eigen::MatrixXd& m) { return m.allFinite(); }

/// r = q - B x as if computed in twice double precision (compensated dot
/// product: the rounding error of every product and sum is carried along
/// with fma and two-sum), portable and without a wider floating type.
void compensated_residual(const Eigen::MatrixXd& B, const Eigen::VectorXd& x, const Eigen::VectorXd& q,
                          Eigen::VectorXd& r)
{
  r.resize(q.size());
  for (Eigen::Index i = 0; i < q.size(); ++i)
  {
    double sum = q(i);
    double error = 0.0;
    for (Eigen::Index j = 0; j < x.size(); ++j)
    {
      const double product = -B(i, j) * x(j);
      const double product_error = std::fma(-B(i, j), x(j), -product);
      const double next = sum + product;
      const double virtual_sum = next - sum;
      const double sum_error = (sum - (next - virtual_sum)) + (product - virtual_sum);
      sum = next;
      error += product_error + sum_error;
    }
    r(i) = sum + error;
  }
}

double natural_residual(const Eigen::VectorXd& z, const Eigen::VectorXd& w)
{
  return z.cwiseMin(w).cwiseAbs().maxCoeff();
}
}  // namespace

LcpResult LemkeSolver::solve(const Eigen::MatrixXd& M, const Eigen::VectorXd& q)
{
  return solve(M, q, Eigen::VectorXd::Ones(q.size()));
}

LcpResult LemkeSolver::solve(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, const Eigen::VectorXd& d)
{
  detail::pin_eigen_blocking();
  LcpResult result;
  const Eigen::Index n = q.size();
  if (M.rows() != n || M.cols() != n || d.size() != n || !all_finite(M) || !q.allFinite() || !d.allFinite() ||
      (n > 0 && d.minCoeff() <= 0.0))
  {
    result.status = LcpStatus::InvalidInput;
    return result;
  }
  result.z = Eigen::VectorXd::Zero(n);
  result.w = q;
  if (n == 0 || q.minCoeff() >= 0.0)
  {
    // z = 0 is complementary already: every w_i = q_i >= 0.
    result.status = LcpStatus::Solved;
    return result;
  }

  n_ = static_cast<int>(n);
  build_tableau(M, q, d);
  result.status = run_pivots(d, result.pivots);
  if (result.status != LcpStatus::Solved)
    return result;
  if (!recover_solution(M, q, result))
    result.status = LcpStatus::NumericalFailure;
  return result;
}

LcpStatus LemkeSolver::run_pivots(const Eigen::VectorXd& d, int& pivots)
{
  const int z0 = 2 * n_;
  const int cap = settings_.max_pivots > 0 ? settings_.max_pivots : kPivotsPerUnknown * n_ + kPivotsBase;
  const int refresh_interval =
      settings_.refresh_interval > 0 ? settings_.refresh_interval : std::max(n_, kMinRefreshInterval);

  // The artificial z0 enters at the row of the most violated q_i / d_i, which
  // makes every basic variable non-negative at once.
  int row = initial_row(d);
  int leaving = basic_[row];
  pivot(row, z0);
  pivots = 1;
  int since_refresh = 1;
  while (leaving != z0)
  {
    if (pivots >= cap)
      return LcpStatus::PivotLimit;
    if (since_refresh >= refresh_interval)
    {
      refresh_tableau();
      since_refresh = 0;
    }
    const int entering = leaving < n_ ? leaving + n_ : leaving - n_;  // complement
    row = ratio_test(entering);
    if (row < 0 && since_refresh > 0)
    {
      // On degenerate problems (many redundant contacts) drift in the
      // tableau can hide the one valid pivot: check with a fresh tableau
      // before calling the problem infeasible.
      refresh_tableau();
      since_refresh = 0;
      row = ratio_test(entering);
    }
    if (row < 0)
      return LcpStatus::RayTermination;
    leaving = basic_[row];
    pivot(row, entering);
    ++pivots;
    ++since_refresh;
  }
  return LcpStatus::Solved;
}

void LemkeSolver::build_tableau(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, const Eigen::VectorXd& d)
{
  const int n = n_;
  tableau_.resize(n, 2 * n + 2);
  tableau_.leftCols(n).setIdentity();
  tableau_.middleCols(n, n) = -M;
  tableau_.col(2 * n) = -d;
  // Normalised so that tie tolerances are relative to the data's scale; the
  // final basis solve uses the original q.
  tableau_.col(2 * n + 1) = q / q.cwiseAbs().maxCoeff();
  original_ = tableau_;
  basic_.resize(n);
  for (int i = 0; i < n; ++i)
    basic_[i] = i;
  pivot_row_.resize(2 * n + 2);
  pivot_column_.resize(n);
  candidates_.reserve(n);
}

void LemkeSolver::pivot(int row, int column)
{
  pivot_row_ = tableau_.row(row) / tableau_(row, column);
  pivot_column_ = tableau_.col(column);
  pivot_column_(row) = 0.0;
  tableau_.noalias() -= pivot_column_ * pivot_row_;
  tableau_.row(row) = pivot_row_;
  // The entering column is exactly a unit vector; do not keep its round-off.
  tableau_.col(column).setZero();
  tableau_(row, column) = 1.0;
  basic_[row] = column;
}

void LemkeSolver::fill_basis_matrix()
{
  basis_.resize(n_, n_);
  for (int i = 0; i < n_; ++i)
    basis_.col(i) = original_.col(basic_[i]);
}

void LemkeSolver::refresh_tableau()
{
  fill_basis_matrix();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(basis_);
  tableau_ = lu.solve(original_);
}

int LemkeSolver::initial_row(const Eigen::VectorXd& d)
{
  // Rows ranked by (q_i, e_i) / d_i; the lexicographic minimum keeps the
  // tableau lexicographically positive from the start.
  pivot_column_ = d;
  const int rhs = 2 * n_ + 1;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n_; ++i)
    best = std::min(best, tableau_(i, rhs) / d(i));
  candidates_.clear();
  for (int i = 0; i < n_; ++i)
    if (tableau_(i, rhs) / d(i) <= best + settings_.tie_tolerance * (std::abs(best) + 1.0 / d(i)))
      candidates_.push_back(i);
  return lexicographic_min();
}

int LemkeSolver::ratio_test(int column)
{
  pivot_column_ = tableau_.col(column);
  const double threshold = settings_.pivot_tolerance * pivot_column_.cwiseAbs().maxCoeff();
  const int rhs = 2 * n_ + 1;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n_; ++i)
    if (pivot_column_(i) > threshold)
      best = std::min(best, tableau_(i, rhs) / pivot_column_(i));
  if (!std::isfinite(best))
    return -1;
  candidates_.clear();
  for (int i = 0; i < n_; ++i)
  {
    const double a = pivot_column_(i);
    if (a > threshold && tableau_(i, rhs) / a <= best + settings_.tie_tolerance * (std::abs(best) + 1.0 / a))
      candidates_.push_back(i);
  }
  // Letting z0 leave whenever it ties ends the run one pivot earlier with a
  // solution of the original problem.
  for (int i : candidates_)
    if (basic_[i] == 2 * n_)
      return i;
  return lexicographic_min();
}

int LemkeSolver::lexicographic_min()
{
  // Ties broken by the rows of B^-1 (the first n tableau columns) divided by
  // the pivot column: distinct rows of a non-singular matrix, so exactly one
  // row wins and no basis repeats (no cycling on degenerate problems).
  for (int j = 0; j < n_ && candidates_.size() > 1; ++j)
  {
    double best = std::numeric_limits<double>::infinity();
    for (int i : candidates_)
      best = std::min(best, tableau_(i, j) / pivot_column_(i));
    auto is_worse = [&](int i) {
      const double value = tableau_(i, j) / pivot_column_(i);
      return value > best + settings_.tie_tolerance * (std::abs(best) + 1.0 / pivot_column_(i));
    };
    candidates_.erase(std::remove_if(candidates_.begin(), candidates_.end(), is_worse), candidates_.end());
  }
  // Only round-off can leave several: fall back to Bland's smallest index.
  return *std::min_element(candidates_.begin(), candidates_.end(),
                           [&](int r, int s) { return basic_[r] < basic_[s]; });
}

bool LemkeSolver::recover_solution(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, LcpResult& result)
{
  fill_basis_matrix();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(basis_);
  // A numerically singular terminal basis means round-off steered the
  // pivots; its "solution" can be huge and still look complementary
  // relative to its own size.
  if (!(lu.rcond() >= kMinBasisRcond))
    return false;
  // Basic variables from the original (unnormalised) q: the tableau only
  // picked the basis. Extreme mass ratios make the basis ill-conditioned
  // (condition numbers near 1e9 at a 1e6 ratio), so the plain solve has a
  // small residual but basic variables that should be 0 come out at 1e-9 of
  // the largest impulse, and clamping them would move speeds by as much.
  // Refinement with residuals in doubled precision restores the forward
  // accuracy (to double epsilon times the largest variable) whenever
  // condition number * double epsilon < 1.
  Eigen::VectorXd x = lu.solve(q);
  for (int step = 0; step < kRefinementSteps; ++step)
  {
    compensated_residual(basis_, x, q, refinement_);
    const Eigen::VectorXd correction = lu.solve(refinement_);
    x += correction;
    if (correction.cwiseAbs().maxCoeff() <= std::numeric_limits<double>::epsilon() * x.cwiseAbs().maxCoeff())
      break;
  }
  // A NaN would pass the checks below: clamping and the maxima skip it.
  if (!x.allFinite())
    return false;
  result.z.setZero();
  for (int i = 0; i < n_; ++i)
    if (basic_[i] >= n_ && basic_[i] < 2 * n_)
      result.z(basic_[i] - n_) = std::max(x(i), 0.0);
  result.w.noalias() = M * result.z;
  const double scale = std::max(q.cwiseAbs().maxCoeff(), result.w.cwiseAbs().maxCoeff());
  result.w += q;
  result.residual = natural_residual(result.z, result.w);
  return std::isfinite(result.residual) && result.residual <= settings_.accept_tolerance * scale;
}

}  // namespace collision2d
