// World: the public API over detail::WorldImpl, and bodies by stable id.
#include "collision2d/world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "world_impl.h"

namespace collision2d
{
namespace
{
/// Body setters do not check, so a body spoiled through them is stopped here:
/// one NaN body would turn its contact partners NaN on the next step.
void validate_state(const Body& b)
{
  if (const char* field = non_finite_state_field(b))
  {
    throw std::invalid_argument(std::string("add_body: non-finite ") + field);
  }
}

/// Static bodies never move, so a velocity given to one is dropped rather
/// than reported as a motion that never happens.
void settle_static(Body& body)
{
  if (body.type() == BodyType::Static)
  {
    body.set_velocity(Vec2{0.0, 0.0});
    body.set_omega(0.0);
  }
}

}  // namespace

World::World(const WorldSettings& settings) : impl_(std::make_unique<detail::WorldImpl>(settings))
{
  validate(settings);
}

World::World(const World& other) : impl_(std::make_unique<detail::WorldImpl>(*other.impl_)) {}
World::World(World&& other) noexcept = default;
World& World::operator=(World&& other) noexcept = default;
World::~World() = default;

World& World::operator=(const World& other)
{
  if (this != &other)
  {
    impl_ = std::make_unique<detail::WorldImpl>(*other.impl_);
  }
  return *this;
}

void World::validate(const WorldSettings& s)
{
  validate_world_settings(s);
}

const WorldSettings& World::settings() const { return impl_->settings_; }

void World::set_settings(const WorldSettings& settings)
{
  impl_->changed();
  validate(settings);
  impl_->settings_ = settings;
}

BodyId World::add_body(const Body& body, const Material& material)
{
  const BodyId id = impl_->next_id_;
  add_body(id, body, material);
  return id;
}

void World::add_body(BodyId id, const Body& body, const Material& material)
{
  impl_->changed();
  if (id < impl_->next_id_)
  {
    throw std::invalid_argument("add_body: id " + std::to_string(id) + " is below the next free id " +
                                std::to_string(impl_->next_id_) + " (ids ascend and are never reused)");
  }
  validate_material(material);
  validate_state(body);
  impl_->append_body(id, body, material);
}

void World::remove_body(BodyId id)
{
  impl_->changed();
  impl_->remove_body(id);
}

bool World::has_body(BodyId id) const
{
  return std::binary_search(impl_->ids_.begin(), impl_->ids_.end(), id);
}

const Body& World::body(BodyId id) const { return impl_->bodies_[impl_->index_of(id)]; }

const Material& World::material(BodyId id) const { return impl_->materials_[impl_->index_of(id)]; }

bool World::is_sleeping(BodyId id) const { return impl_->asleep_[impl_->index_of(id)]; }

void World::set_body_state(BodyId id, Vec2 position, double theta, Vec2 velocity, double omega)
{
  impl_->changed();
  const std::size_t i = impl_->index_of(id);
  if (!is_finite(position) || !std::isfinite(theta) || !is_finite(velocity) || !std::isfinite(omega))
  {
    throw std::invalid_argument("set_body_state: non-finite state for body " + std::to_string(id));
  }
  Body& b = impl_->bodies_[i];
  b.set_position(position);
  b.set_theta(theta);
  b.set_velocity(velocity);
  b.set_omega(omega);
  settle_static(b);
  impl_->wake(i);
}

void World::set_body_type(BodyId id, BodyType type)
{
  impl_->changed();
  const std::size_t i = impl_->index_of(id);
  impl_->make_room_to_move_contacts(impl_->contacts_.size());  // waking cannot run out of memory then
  Body& b = impl_->bodies_[i];
  b.set_type(type);
  settle_static(b);
  impl_->wake(i);
}

std::vector<BodyId> World::body_ids() const { return impl_->ids_; }

std::size_t World::body_count() const { return impl_->bodies_.size(); }

BodyId World::next_id() const { return impl_->next_id_; }

void World::set_next_id(BodyId id)
{
  impl_->changed();
  if (id < impl_->next_id_)
  {
    throw std::invalid_argument("set_next_id: " + std::to_string(id) + " is below the next free id " +
                                std::to_string(impl_->next_id_));
  }
  impl_->next_id_ = id;
}

void World::clear()
{
  impl_->changed();
  impl_->clear();
}

StepReport World::step(int frames) { return impl_->step(frames); }

const std::vector<WorldContact>& World::contacts() const { return impl_->all_contacts(); }

double World::time() const { return impl_->time_; }

std::uint64_t World::frame_count() const { return impl_->frame_count_; }

void World::set_clock(double time, std::uint64_t frame_count)
{
  impl_->changed();
  if (!(std::isfinite(time) && time >= 0.0))
  {
    throw std::invalid_argument("set_clock: time must be finite and >= 0 (got " + std::to_string(time) + ")");
  }
  impl_->time_ = time;
  impl_->frame_count_ = frame_count;
}

StepState World::step_state() const
{
  const detail::WorldImpl& w = *impl_;
  StepState state;
  state.contacts = w.all_contacts();
  state.contact_substep = w.cache_h_;
  for (std::size_t i = 0; i < w.ids_.size(); ++i)
  {
    if (w.asleep_[i])
    {
      state.asleep.push_back(w.ids_[i]);
    }
  }
  state.rest_time = w.rest_time_;
  return state;
}

void World::set_step_state(const StepState& state)
{
  impl_->changed();
  detail::WorldImpl& w = *impl_;
  const std::string where = "set_step_state: ";
  if (!(std::isfinite(state.contact_substep) && state.contact_substep >= 0.0))
  {
    throw std::invalid_argument(where + "contact_substep must be finite and >= 0");
  }
  if (state.rest_time.size() != w.bodies_.size())
  {
    throw std::invalid_argument(where + std::to_string(state.rest_time.size()) + " rest times for " +
                                std::to_string(w.bodies_.size()) + " bodies");
  }
  std::vector<WorldContact> contacts = state.contacts;
  for (std::size_t k = 0; k < contacts.size(); ++k)
  {
    WorldContact& c = contacts[k];
    if (!has_body(c.a) || !has_body(c.b) || !(c.a < c.b))
    {
      throw std::invalid_argument(where + "contacts[" + std::to_string(k) + "] names bodies " + std::to_string(c.a) +
                                  " and " + std::to_string(c.b) + " (known ids, a < b)");
    }
    if (!is_finite(c.contact.normal) || !is_finite(c.contact.point) || !std::isfinite(c.contact.penetration) ||
        !std::isfinite(c.impulse.normal) || !std::isfinite(c.impulse.tangent) || !std::isfinite(c.anchor_drift) ||
        !is_finite(c.origin.r_a) || !is_finite(c.origin.r_b) || !std::isfinite(c.origin.separation) ||
        !std::isfinite(c.origin.theta_a) || !std::isfinite(c.origin.theta_b))
    {
      throw std::invalid_argument(where + "contacts[" + std::to_string(k) + "] is not finite");
    }
    c.contact.a = w.index_of(c.a);
    c.contact.b = w.index_of(c.b);
  }
  std::vector<unsigned char> asleep(w.bodies_.size(), 0);
  for (BodyId id : state.asleep)
  {
    if (!has_body(id))
    {
      throw std::invalid_argument(where + "asleep names unknown body " + std::to_string(id));
    }
    // Only a dynamic body sleeps: a kinematic one marked asleep would stay
    // where it is, whatever its velocity, until something woke it.
    const std::size_t i = w.index_of(id);
    if (w.bodies_[i].type() != BodyType::Dynamic)
    {
      throw std::invalid_argument(where + "asleep names body " + std::to_string(id) +
                                  ", which is not dynamic (only a dynamic body sleeps)");
    }
    asleep[i] = true;
  }
  for (double t : state.rest_time)
  {
    if (!(std::isfinite(t) && t >= 0.0))
    {
      throw std::invalid_argument(where + "a rest time is not finite and >= 0");
    }
  }
  // Sorting out what sleeps moves the contacts into two lists: room first,
  // so running out of memory refuses the state before anything changes.
  w.make_room_to_move_contacts(contacts.size());
  w.contacts_ = std::move(contacts);
  w.cache_h_ = state.contact_substep;
  w.asleep_ = std::move(asleep);
  w.rest_time_ = state.rest_time;
  w.points_.clear();
  w.sort_out_sleeping();
}

namespace detail
{
void WorldImpl::append_body(BodyId id, const Body& body, const Material& material)
{
  // What can run out of memory comes first (the copy of a polygon's outline,
  // room in every per-body list), so a refused add changes nothing.
  Body added = body;
  settle_static(added);
  const std::size_t n = bodies_.size() + 1;
  make_room(bodies_, n);
  make_room(materials_, n);
  make_room(ids_, n);
  make_room(asleep_, n);
  make_room(island_label_, n);
  make_room(rest_time_, n);
  make_room(inner_radius_, n);
  make_room(disk_, n);
  if (clamping_)
  {
    make_room(toi_, n);
  }
  bodies_.push_back(std::move(added));
  materials_.push_back(material);
  ids_.push_back(id);
  next_id_ = id + 1;
  asleep_.push_back(false);
  island_label_.push_back(0);
  rest_time_.push_back(0.0);
  if (clamping_)
  {
    toi_.push_back(1.0);  // the next detection reads it: a new body was not stopped
  }
  append_body_shape(bodies_.back());
}

void WorldImpl::remove_body(BodyId id)
{
  const std::size_t i = index_of(id);
  // Bodies resting on the removed one must fall, so its partners wake (a
  // sleeping partner with its island).
  std::vector<std::size_t> partners;
  for (const std::vector<WorldContact>* list : {&contacts_, &sleeping_contacts_})
  {
    for (const WorldContact& c : *list)
    {
      if (c.a == id || c.b == id)
      {
        partners.push_back(c.a == id ? c.contact.b : c.contact.a);
      }
    }
  }
  // Waking moves contacts between lists: room first, so a refused removal
  // wakes nothing.
  make_room_to_move_contacts(contacts_.size());
  for (std::size_t partner : partners)
  {
    wake(partner);
  }
  const auto offset = static_cast<std::ptrdiff_t>(i);
  bodies_.erase(bodies_.begin() + offset);
  materials_.erase(materials_.begin() + offset);
  ids_.erase(ids_.begin() + offset);
  asleep_.erase(asleep_.begin() + offset);
  island_label_.erase(island_label_.begin() + offset);
  rest_time_.erase(rest_time_.begin() + offset);
  if (clamping_)
  {
    toi_.erase(toi_.begin() + offset);
  }
  // The removed body's contacts go; the others follow the shifted dense indices.
  for (std::vector<WorldContact>* list : {&contacts_, &sleeping_contacts_})
  {
    list->erase(std::remove_if(list->begin(), list->end(),
                               [id](const WorldContact& c) { return c.a == id || c.b == id; }),
                list->end());
    for (WorldContact& c : *list)
    {
      c.contact.a -= c.contact.a > i ? 1 : 0;
      c.contact.b -= c.contact.b > i ? 1 : 0;
    }
  }
  measure_sleeping_penetration();
  refresh_body_shapes();
}

std::size_t WorldImpl::index_of(BodyId id) const
{
  // ids_ stays sorted: new ids are larger than every existing one and
  // removal preserves order.
  const auto it = std::lower_bound(ids_.begin(), ids_.end(), id);
  if (it == ids_.end() || *it != id)
  {
    throw std::out_of_range("unknown body id " + std::to_string(id));
  }
  return static_cast<std::size_t>(it - ids_.begin());
}

void WorldImpl::wake(std::size_t index)
{
  if (asleep_[index])
  {
    wake_island(island_label_[index], contacts_);         // world_sleeping_contacts.cpp
  }
  rest_time_[index] = 0.0;
}

void WorldImpl::clear()
{
  bodies_.clear();
  materials_.clear();
  ids_.clear();
  asleep_.clear();
  island_label_.clear();
  rest_time_.clear();
  contacts_.clear();
  sleeping_contacts_.clear();
  sleeping_penetration_ = 0.0;
  points_.clear();
  clamping_ = false;
  refresh_body_shapes();
}

}  // namespace detail
}  // namespace collision2d
