// `.collision` scenario files: a line-oriented parser whose every rejection
// names the source and line, so a user can fix a file from the message alone.
#include "collision2d/scenario_io.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace collision2d
{
namespace
{
constexpr char kCommentMark = '#';
/// Fields of a `poly` line before its vertex coordinates: m px py theta vx vy w k.
constexpr std::size_t kPolyHeaderFields = 8;
constexpr std::size_t kMinBodies = 2;

struct Location
{
  const std::string& source;
  std::size_t line;
};

[[noreturn]] void fail(const Location& at, const std::string& what)
{
  throw std::runtime_error(at.source + ":" + std::to_string(at.line) + ": " + what);
}

/// A number as the user would write it (1.5, not 1.500000).
std::string show(double value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

/// Whitespace-separated tokens of a line, ignoring everything from `#` on.
std::vector<std::string> tokenize(const std::string& line)
{
  std::istringstream words(line.substr(0, line.find(kCommentMark)));
  std::vector<std::string> tokens;
  std::string token;
  while (words >> token)
  {
    tokens.push_back(token);
  }
  return tokens;
}

/// The fields after a line's keyword, read in order with errors that name the
/// line, the keyword and the field.
class Fields
{
public:
  Fields(std::vector<std::string> tokens, const Location& at) : tokens_(std::move(tokens)), at_(at) {}

  const std::string& keyword() const { return tokens_.front(); }
  std::size_t remaining() const { return tokens_.size() - next_; }

  double number(const std::string& field)
  {
    if (next_ >= tokens_.size())
    {
      fail(at_, "'" + keyword() + "' is missing field " + field);
    }
    const std::string& token = tokens_[next_++];
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0')
    {
      fail(at_, "field " + field + " of '" + keyword() + "' is not a number: '" + token + "'");
    }
    if (!std::isfinite(value))
    {
      fail(at_, "field " + field + " of '" + keyword() + "' is not finite: '" + token + "'");
    }
    return value;
  }

  void expect_end() const
  {
    if (next_ < tokens_.size())
    {
      fail(at_, "'" + keyword() + "' has " + std::to_string(remaining()) + " extra field(s), starting at '" +
                    tokens_[next_] + "'");
    }
  }

private:
  std::vector<std::string> tokens_;
  std::size_t next_ = 1;  // token 0 is the keyword
  Location at_;
};

/// Constructs a body, turning the constructor's std::invalid_argument into a
/// parse error that names the line.
template <typename... Args>
Body make_body(const Location& at, Args&&... args)
{
  try
  {
    return Body(std::forward<Args>(args)...);
  }
  catch (const std::invalid_argument& e)
  {
    fail(at, std::string("invalid body: ") + e.what());
  }
}

/// body <m> <R> <px> <py> <vx> <vy> [w]
Body parse_disk(Fields& f, const Location& at)
{
  const double m = f.number("m");
  const double r = f.number("R");
  const Vec2 p{f.number("px"), f.number("py")};
  const Vec2 v{f.number("vx"), f.number("vy")};
  const double w = f.remaining() > 0 ? f.number("w") : 0.0;
  f.expect_end();
  return make_body(at, m, r, p, v, w);
}

/// k as a vertex count: a whole number whose coordinates the line provides.
std::size_t vertex_count(double k, const Fields& f, const Location& at)
{
  if (k < 0.0 || k != std::floor(k))
  {
    fail(at, "vertex count k of 'poly' must be a whole number >= 0, got " + show(k));
  }
  const double coordinates = static_cast<double>(f.remaining());
  if (2.0 * k != coordinates)
  {
    fail(at, "vertex count mismatch: 'poly' declares k = " + show(k) + " vertices, which needs " + show(2.0 * k) +
                 " coordinates, but the line has " + std::to_string(f.remaining()));
  }
  return static_cast<std::size_t>(k);
}

/// poly <m> <px> <py> <theta> <vx> <vy> <w> <k> <x0> <y0> ... <x(k-1)> <y(k-1)>
Body parse_polygon(Fields& f, const Location& at)
{
  const double m = f.number("m");
  const Vec2 p{f.number("px"), f.number("py")};
  const double theta = f.number("theta");
  const Vec2 v{f.number("vx"), f.number("vy")};
  const double w = f.number("w");
  const std::size_t k = vertex_count(f.number("k"), f, at);
  std::vector<Vec2> vertices;
  vertices.reserve(k);
  for (std::size_t i = 0; i < k; ++i)
  {
    const std::string index = std::to_string(i);
    vertices.push_back({f.number("x" + index), f.number("y" + index)});
  }
  f.expect_end();
  return make_body(at, m, vertices, p, v, theta, w);
}

/// A scalar setting that may be given once, with its allowed range.
struct Setting
{
  const char* field;
  double lo;
  double hi;
  const char* range;
  double value = 0.0;
  std::size_t line = 0;  ///< 0 while not given
};

void parse_setting(Fields& f, const Location& at, Setting& setting)
{
  if (setting.line != 0)
  {
    fail(at, "duplicate '" + f.keyword() + "' (first given on line " + std::to_string(setting.line) + ")");
  }
  const double value = f.number(setting.field);
  f.expect_end();
  if (value < setting.lo || value > setting.hi)
  {
    fail(at, f.keyword() + " must be " + setting.range + ", got " + show(value));
  }
  setting.value = value;
  setting.line = at.line;
}

}  // namespace

Scenario parse_scenario(std::istream& in, const std::string& source_name)
{
  Scenario scenario;
  Setting restitution{"e", 0.0, 1.0, "in [0, 1]"};
  Setting friction{"mu", 0.0, HUGE_VAL, ">= 0"};
  std::string line;
  std::size_t line_number = 0;
  while (std::getline(in, line))
  {
    const Location at{source_name, ++line_number};
    std::vector<std::string> tokens = tokenize(line);
    if (tokens.empty())
    {
      continue;
    }
    Fields fields(std::move(tokens), at);
    const std::string& keyword = fields.keyword();
    if (keyword == "body")
    {
      scenario.bodies.push_back(parse_disk(fields, at));
    }
    else if (keyword == "poly")
    {
      scenario.bodies.push_back(parse_polygon(fields, at));
    }
    else if (keyword == "restitution")
    {
      parse_setting(fields, at, restitution);
    }
    else if (keyword == "friction")
    {
      parse_setting(fields, at, friction);
    }
    else
    {
      fail(at, "unknown keyword '" + keyword + "' (expected body, poly, restitution or friction)");
    }
  }
  const Location end{source_name, line_number};
  if (scenario.bodies.size() < kMinBodies)
  {
    fail(end, "end of input: a scenario needs at least " + std::to_string(kMinBodies) + " bodies, found " +
                  std::to_string(scenario.bodies.size()));
  }
  if (restitution.line == 0)
  {
    fail(end, "end of input: missing 'restitution <e>' line");
  }
  scenario.restitution = restitution.value;
  scenario.friction = friction.value;
  return scenario;
}

Scenario load_scenario(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
  {
    throw std::runtime_error(path + ": cannot open scenario file");
  }
  return parse_scenario(in, path);
}

}  // namespace collision2d
