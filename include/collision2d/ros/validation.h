// Checks of request fields for the ROS face. The core rejects bad bodies and
// settings too, but with messages that cannot say which body of a request was
// wrong; these name the body (index and id) and the field.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/vec2.h"

namespace collision2d
{
namespace ros_interface
{
/// A request the node cannot serve. what() reads "<where>: <what is wrong>",
/// e.g. "bodies[3] (id 7): mass = -1 must be > 0".
class InvalidRequest : public std::invalid_argument
{
public:
  using std::invalid_argument::invalid_argument;
};

/// Throws InvalidRequest "<where>: <problem>".
[[noreturn]] void reject(const std::string& where, const std::string& problem);

/// How messages name the index-th body of a request: "bodies[3] (id 7)".
std::string body_label(std::size_t index, std::uint32_t id);
/// Shortest text that reads back as the same double ("nan", "inf" included).
std::string format_number(double value);

void require_finite(double value, const std::string& where, const std::string& field);
/// Finite and > 0.
void require_positive(double value, const std::string& where, const std::string& field);
/// Finite and >= 0.
void require_non_negative(double value, const std::string& where, const std::string& field);
/// Finite and in [lo, hi].
void require_in_range(double value, double lo, double hi, const std::string& where, const std::string& field);

/// A convex polygon outline: at least 3 vertices, no vertex repeating its
/// predecessor, non-zero area, counter-clockwise, turning left at every vertex
/// and winding around once.
void check_polygon_outline(const std::vector<Vec2>& vertices, const std::string& where);

/// Two bodies sharing a centre always overlap and have no defined contact
/// normal; throws naming both. `labels[i]` names centres[i]. O(n log n).
void check_distinct_centres(const std::vector<Vec2>& centres, const std::vector<std::string>& labels);

}  // namespace ros_interface
}  // namespace collision2d
