// LimitMassRange (include/manyworlds/mass_range.h): union-find over the
// constraints between dynamic bodies, then one pass for each group's heaviest
// mass and one to raise the bodies below heaviest / max_ratio.
#include "manyworlds/mass_range.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

namespace manyworlds {
namespace {

// A body whose mass the solver sees: dynamic, a finite positive mass, and
// free to translate (with every translation locked its inverse mass is 0, so
// to the joints it is the ground, like a kinematic body).
bool MassCounts(const BodySettings& body) {
  return body.motion_type == MotionType::kDynamic && std::isfinite(body.mass) &&
         body.mass > 0.0f && AllowsTranslation(body.allowed_dofs);
}

// Groups of bodies with path halving; only bodies whose mass counts are ever
// joined.
class Groups {
 public:
  explicit Groups(std::size_t count) : parent_(count) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t Root(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void Join(std::size_t a, std::size_t b) { parent_[Root(a)] = Root(b); }

 private:
  std::vector<std::size_t> parent_;
};

}  // namespace

std::vector<MassRaise> LimitMassRange(Scene& scene, float max_ratio) {
  if (!(std::isfinite(max_ratio) && max_ratio >= 1.0f)) {
    throw std::invalid_argument("LimitMassRange: max_ratio must be finite and >= 1 (got " +
                                std::to_string(max_ratio) + ")");
  }
  std::vector<BodySettings>& bodies = scene.bodies();
  Groups groups(bodies.size());
  for (const ConstraintSettings& constraint : scene.constraints()) {
    const auto [body1, body2] = std::visit(
        [](const auto& s) { return std::pair{s.body1, s.body2}; }, constraint);
    if (body1 < bodies.size() && body2 < bodies.size() && MassCounts(bodies[body1]) &&
        MassCounts(bodies[body2])) {
      groups.Join(body1, body2);
    }
  }
  std::vector<float> heaviest(bodies.size(), 0.0f);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!MassCounts(bodies[i])) continue;
    float& group_max = heaviest[groups.Root(i)];
    group_max = std::max(group_max, bodies[i].mass);
  }
  std::vector<MassRaise> raised;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    BodySettings& body = bodies[i];
    if (!MassCounts(body)) continue;
    const float floor = heaviest[groups.Root(i)] / max_ratio;
    if (!(body.mass < floor)) continue;
    // In double: a factor beyond float's range makes the inertia infinite,
    // which Batch then refuses naming the body, rather than rounding it.
    const double factor = double(floor) / double(body.mass);
    body.mass = floor;
    for (float& moment : body.inertia_diagonal) moment = float(double(moment) * factor);
    raised.push_back(MassRaise{i, factor});
  }
  return raised;
}

}  // namespace manyworlds
