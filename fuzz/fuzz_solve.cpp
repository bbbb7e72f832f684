// libFuzzer target: raw bytes -> bodies and solver settings -> one of
// ContactSolver::resolve, step, solve + correct_positions, or solve_exact.
// Scenes are built near each other so they touch, at a fuzzed scale
// (1e-4..1e4 m), offset (origin or 1e6 m), speed, spin and mass ratio, with
// disks and convex polygons up to aspect 1000. Occasionally a field takes a
// raw double (NaN, inf, 1e308, ...) to exercise the rejections.
// Checked: no sanitizer report; only documented exceptions (invalid_argument
// for rejected input, runtime_error for an undefined normal, overflow_error
// only outside the promised ranges and with the bodies left as they were);
// finite output always; conserved linear momentum for in-range scenes of
// dynamic bodies;
// an exact fallback leaves the bodies untouched.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/exact_solver.h"
#include "fuzz_support.h"

using namespace collision2d;

namespace
{
constexpr double kTwoPi = 6.283185307179586;
constexpr int kMinBodies = 2;
constexpr int kMaxBodies = 12;
constexpr int kMaxVertices = 12;
constexpr int kMaxIterations = 128;
constexpr double kFarOffset = 1e6;          ///< m
constexpr double kMaxAspect = 1000.0;       ///< sliver polygons
constexpr double kMomentumRelativeTol = 1e-9;
constexpr int kRawInputOneIn = 8;  ///< inputs that may carry raw double fields
constexpr int kRawFieldOneIn = 8;  ///< within such an input, fields that are raw

enum class Mode
{
  Resolve,
  Step,
  SolveAndCorrect,
  Exact,
  kMaxValue = Exact
};

/// Draws fields. One input in kRawInputOneIn may replace fields by
/// unconstrained doubles; the others stay in range, so the finite-output and
/// momentum checks apply to most inputs.
class Draw
{
public:
  explicit Draw(FuzzedDataProvider& in) : in_(in), raw_allowed_(in.ConsumeIntegralInRange(0, kRawInputOneIn - 1) == 0)
  {
  }

  double range(double lo, double hi)
  {
    if (raw_allowed_ && in_.ConsumeIntegralInRange(0, kRawFieldOneIn - 1) == 0)
    {
      raw_ = true;
      return in_.ConsumeFloatingPoint<double>();
    }
    return in_.ConsumeFloatingPointInRange(lo, hi);
  }
  double log_range(double lo, double hi) { return std::exp(range(std::log(lo), std::log(hi))); }
  bool used_raw() const { return raw_; }
  FuzzedDataProvider& in() { return in_; }

private:
  FuzzedDataProvider& in_;
  bool raw_allowed_;
  bool raw_ = false;
};

std::vector<Vec2> ellipse_outline(Draw& draw, double size)
{
  const int k = draw.in().ConsumeIntegralInRange(3, kMaxVertices);
  const double aspect = draw.log_range(1.0, kMaxAspect);
  std::vector<double> angles;
  for (int i = 0; i < k; ++i)
  {
    angles.push_back(draw.range(0.0, kTwoPi));
  }
  std::sort(angles.begin(), angles.end());
  std::vector<Vec2> outline;
  for (double a : angles)
  {
    outline.push_back({size * std::cos(a), size / aspect * std::sin(a)});
  }
  return outline;
}

Body polygon_body(Draw& draw, double mass, double size, Vec2 p, Vec2 v, double omega)
{
  std::vector<Vec2> outline = ellipse_outline(draw, size);  // drawn before the angle, as clang orders the arguments
  const double theta = draw.range(-kTwoPi, kTwoPi);
  return Body(mass, outline, p, v, theta, omega);
}

Body make_body(Draw& draw, double scale, Vec2 offset, double speed)
{
  const double mass = draw.log_range(fuzz::kMinMass, fuzz::kMaxMass);
  const double size = scale * draw.log_range(0.05, 2.0);
  const Vec2 p = offset + scale * Vec2{draw.range(-2.0, 2.0), draw.range(-2.0, 2.0)};
  const Vec2 v{speed * draw.range(-1.0, 1.0), speed * draw.range(-1.0, 1.0)};
  const double spin = draw.range(-fuzz::kMaxSpin, fuzz::kMaxSpin);
  const double omega = spin * draw.range(0.0, 1.0);
  const bool disk = draw.in().ConsumeBool();
  Body body = disk ? Body(mass, size, p, v, omega) : polygon_body(draw, mass, size, p, v, omega);
  switch (draw.in().ConsumeIntegralInRange(0, 9))
  {
    case 0:
      body.set_type(BodyType::Static);
      body.set_velocity({});
      body.set_omega(0.0);
      break;
    case 1:
      body.set_type(BodyType::Kinematic);
      break;
    default:
      break;
  }
  return body;
}

Vec2 momentum(const std::vector<Body>& bodies, double& scale)
{
  Vec2 p;
  for (const Body& b : bodies)
  {
    p += b.momentum();
    scale += length(b.momentum());
  }
  return p;
}

bool all_dynamic(const std::vector<Body>& bodies)
{
  return std::all_of(bodies.begin(), bodies.end(), [](const Body& b) { return b.type() == BodyType::Dynamic; });
}

SolveReport run(Mode mode, const ContactSolver& solver, std::vector<Body>& bodies, double& impulse_scale)
{
  switch (mode)
  {
    case Mode::Resolve:
      return solver.resolve(bodies);
    case Mode::Step:
      return solver.step(bodies);
    case Mode::SolveAndCorrect:
    {
      const std::vector<Contact> contacts = ContactSolver::detect_contacts(bodies);
      const SolveReport report = solver.solve(bodies, contacts);
      solver.correct_positions(bodies, contacts);
      impulse_scale = report.total_normal_impulse;
      return report;
    }
    case Mode::Exact:
    {
      const std::vector<Body> before = bodies;
      const std::vector<Contact> contacts = ContactSolver::detect_contacts(bodies);
      std::vector<ContactImpulse> impulses;
      const SolveReport report =
          solve_exact(bodies, contacts, solver.restitution(), solver.friction(), solver.tolerance(), &impulses);
      if (report.exact_fallback)
      {
        for (std::size_t i = 0; i < bodies.size(); ++i)
        {
          fuzz::require(bodies[i].velocity() == before[i].velocity() && bodies[i].omega() == before[i].omega(),
                        "exact fallback modified a body");
        }
      }
      impulse_scale = report.total_normal_impulse;
      return report;
    }
  }
  return {};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  FuzzedDataProvider in(data, size);
  Draw draw(in);
  const Mode mode = in.ConsumeEnum<Mode>();
  const double scale = std::pow(10.0, in.ConsumeIntegralInRange(-4, 4));
  const Vec2 offset = in.ConsumeBool() ? Vec2{kFarOffset, -kFarOffset} : Vec2{};
  const double speed = std::pow(10.0, in.ConsumeIntegralInRange(-2, 4));
  std::vector<Body> bodies;
  std::vector<Body> bodies_before;
  bool check = false;
  try
  {
    // One draw a statement: the order of a call's arguments is the
    // compiler's, and an input must decode alike under clang and gcc.
    const double restitution = draw.range(0.0, 1.0);
    const double friction = draw.range(0.0, 2.0);
    const int iterations = in.ConsumeIntegralInRange(1, kMaxIterations);
    const double tolerance = draw.log_range(1e-14, 1e-3);
    const double bias_factor = draw.range(0.0, 1.0);
    const double slop = scale * draw.range(0.0, 0.01);
    const ContactSolver solver(restitution, friction, iterations, tolerance, bias_factor, slop);
    const int count = in.ConsumeIntegralInRange(kMinBodies, kMaxBodies);
    for (int i = 0; i < count; ++i)
    {
      bodies.push_back(make_body(draw, scale, offset, speed));
    }
    check = !draw.used_raw() && fuzz::in_range(bodies);
    bodies_before = bodies;
    double p_scale = 0.0;
    const Vec2 p_before = momentum(bodies, p_scale);
    double impulse_scale = 0.0;
    const SolveReport report = run(mode, solver, bodies, impulse_scale);
    // No entry point hands back a non-finite body: they throw instead.
    fuzz::require_finite(bodies, "solve gave a non-finite body");
    if (check)
    {
      fuzz::require(std::isfinite(report.max_residual) && std::isfinite(report.total_normal_impulse),
                    "in-range solve gave a non-finite report");
      const Vec2 p_after = momentum(bodies, p_scale);
      if (all_dynamic(bodies))
      {
        fuzz::require(length(p_after - p_before) <= kMomentumRelativeTol * (p_scale + impulse_scale),
                      "linear momentum not conserved");
      }
    }
  }
  catch (const std::invalid_argument&)
  {
    return 0;  // rejected input (raw fields, degenerate outlines, NaN settings)
  }
  catch (const std::overflow_error&)
  {
    fuzz::require(!check, "in-range solve overflowed");
    // resolve() and step() are all-or-nothing.
    fuzz::require(mode == Mode::SolveAndCorrect || fuzz::same_state(bodies_before, bodies),
                  "an overflowed solve changed the bodies");
    return 0;
  }
  catch (const std::runtime_error&)
  {
    return 0;  // undefined normal: coincident centres
  }
  return 0;
}
