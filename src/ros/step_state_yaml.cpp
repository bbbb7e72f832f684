#include "collision2d/ros/step_state_yaml.h"

#include <stdexcept>
#include <vector>

#include "collision2d/ros/validation.h"

namespace collision2d
{
namespace ros_interface
{
const char* const kStepStateKeys[4] = {"contact_substep", "asleep", "rest_time", "contacts"};

namespace
{
[[noreturn]] void malformed(const std::string& source, const std::string& problem)
{
  throw std::runtime_error(source + ": snapshot: " + problem);
}

void write_vec(std::ostream& out, Vec2 v)
{
  out << "[" << format_number(v.x) << ", " << format_number(v.y) << "]";
}

Vec2 read_vec(const YAML::Node& node)
{
  const std::vector<double> xy = node.as<std::vector<double>>();
  if (xy.size() != 2)
  {
    throw YAML::Exception(YAML::Mark::null_mark(), "not a pair");
  }
  return Vec2{xy[0], xy[1]};
}

WorldContact read_contact(const YAML::Node& node)
{
  WorldContact c;
  c.a = node["a"].as<BodyId>();
  c.b = node["b"].as<BodyId>();
  c.contact.feature = node["feature"].as<std::uint32_t>();
  c.contact.normal = read_vec(node["normal"]);
  c.contact.point = read_vec(node["point"]);
  c.contact.penetration = node["depth"].as<double>();
  const Vec2 impulse = read_vec(node["impulse"]);
  c.impulse = ContactImpulse{impulse.x, impulse.y};
  c.sliding = node["sliding"].as<bool>();
  // Snapshots written before anchors existed have none: the contact restarts from where it is.
  c.anchor_drift = node["anchor"] ? node["anchor"].as<double>() : 0.0;
  // ... nor origins: the next frame finds the contact's points again.
  if (const YAML::Node origin = node["origin"])
  {
    c.origin.r_a = read_vec(origin["r_a"]);
    c.origin.r_b = read_vec(origin["r_b"]);
    c.origin.separation = origin["gap"].as<double>();
    c.origin.theta_a = origin["theta_a"].as<double>();
    c.origin.theta_b = origin["theta_b"].as<double>();
    c.origin.known = true;
  }
  return c;
}

}  // namespace

void write_step_state(std::ostream& out, const StepState& state)
{
  out << "# Warm starting and sleep: a loaded snapshot steps on exactly as the saved world.\n";
  out << "contact_substep: " << format_number(state.contact_substep) << "\n";
  out << "asleep: [";
  for (std::size_t i = 0; i < state.asleep.size(); ++i)
  {
    out << (i == 0 ? "" : ", ") << state.asleep[i];
  }
  out << "]\nrest_time: [";
  for (std::size_t i = 0; i < state.rest_time.size(); ++i)
  {
    out << (i == 0 ? "" : ", ") << format_number(state.rest_time[i]);
  }
  out << "]\ncontacts:" << (state.contacts.empty() ? " []" : "") << "\n";
  for (const WorldContact& c : state.contacts)
  {
    out << "  - {a: " << c.a << ", b: " << c.b << ", feature: " << c.contact.feature << ", normal: ";
    write_vec(out, c.contact.normal);
    out << ", point: ";
    write_vec(out, c.contact.point);
    out << ", depth: " << format_number(c.contact.penetration) << ", impulse: ";
    write_vec(out, Vec2{c.impulse.normal, c.impulse.tangent});
    out << ", sliding: " << (c.sliding ? "true" : "false") << ", anchor: " << format_number(c.anchor_drift);
    if (c.origin.known)
    {
      out << ", origin: {r_a: ";
      write_vec(out, c.origin.r_a);
      out << ", r_b: ";
      write_vec(out, c.origin.r_b);
      out << ", gap: " << format_number(c.origin.separation) << ", theta_a: " << format_number(c.origin.theta_a)
          << ", theta_b: " << format_number(c.origin.theta_b) << "}";
    }
    out << "}\n";
  }
}

StepState read_step_state(const YAML::Node& doc, const std::string& source)
{
  StepState state;
  const char* key = "";
  try
  {
    key = "contact_substep";
    if (doc[key])
    {
      state.contact_substep = doc[key].as<double>();
    }
    key = "asleep";
    if (doc[key])
    {
      state.asleep = doc[key].as<std::vector<BodyId>>();
    }
    key = "rest_time";
    if (doc[key])
    {
      state.rest_time = doc[key].as<std::vector<double>>();
    }
    key = "contacts";
    for (std::size_t k = 0; doc[key] && k < doc[key].size(); ++k)
    {
      state.contacts.push_back(read_contact(doc[key][k]));
    }
  }
  catch (const YAML::Exception&)
  {
    malformed(source, std::string("'") + key + "' holds an invalid entry");
  }
  return state;
}

}  // namespace ros_interface
}  // namespace collision2d
