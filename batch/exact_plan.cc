// Elimination order and fill of the exact joint solve (batch/exact_plan.h).

#include "batch/exact_plan.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "batch/plan.h"
#include "manyworlds/scene.h"

namespace manyworlds {

int ExactRowCount(ExactRows rows) {
  switch (rows) {
    case ExactRows::kPoint: case ExactRows::kRotation: return 3;
    case ExactRows::kHingeRotation: case ExactRows::kSliderAxes: return 2;
    case ExactRows::kGear: case ExactRows::kRackAndPinion: case ExactRows::kDistance: return 1;
  }
  return 0;
}

bool HasLinearRows(ExactRows rows, int side) {
  switch (rows) {
    case ExactRows::kPoint: case ExactRows::kSliderAxes: case ExactRows::kDistance: return true;
    case ExactRows::kHingeRotation: case ExactRows::kRotation: case ExactRows::kGear: return false;
    case ExactRows::kRackAndPinion: return side == 1;
  }
  return true;
}

std::size_t ExactSolvePlan::fill_blocks() const {
  std::set<std::size_t> coupled;
  for (const SharedBody& shared : shared_bodies) coupled.insert(shared.block);
  return blocks.size() - coupled.size();
}

bool ExactSolvePlan::only_points() const {
  return std::all_of(order.begin(), order.end(),
                     [](const Group& g) { return g.rows == ExactRows::kPoint; });
}

namespace {

// The row groups of a constraint the exact solve factors; empty for the
// constraints it leaves whole to Gauss-Seidel (SolvedWhole). A six-DOF
// constraint's groups are its all-fixed shortcuts (batch/plan.h,
// SixDofConfig), in the fixed constraint's order.
std::vector<ExactRows> GroupsOf(const ConstraintPlan& c) {
  switch (c.type) {
    case ConstraintType::kPoint: return {ExactRows::kPoint};
    case ConstraintType::kHinge: return {ExactRows::kPoint, ExactRows::kHingeRotation};
    case ConstraintType::kFixed: return {ExactRows::kPoint, ExactRows::kRotation};
    case ConstraintType::kSlider: return {ExactRows::kSliderAxes, ExactRows::kRotation};
    case ConstraintType::kGear: return {ExactRows::kGear};
    case ConstraintType::kRackAndPinion: return {ExactRows::kRackAndPinion};
    case ConstraintType::kSwingTwist: return {ExactRows::kPoint};  // limits and drives bounded
    case ConstraintType::kCone: return {ExactRows::kPoint};        // the cone row bounded
    case ConstraintType::kSixDof: {
      std::vector<ExactRows> groups;
      if (c.six_dof.translation_point) groups.push_back(ExactRows::kPoint);
      if (c.six_dof.rotation_euler) groups.push_back(ExactRows::kRotation);
      return groups;
    }
    case ConstraintType::kDistance:
      if (c.rod_group) return {ExactRows::kDistance};
      return {};
    case ConstraintType::kPulley: case ConstraintType::kPath:  // SolvedWhole
      return {};
  }
  return {};
}

// A six-DOF constraint's rows beside its groups (translation rows and
// drives where translation is not the point shortcut, swing-twist rows and
// drives where rotation is not the Euler one; an all-fixed shortcut's
// drives are not used, as in Jolt), and whether any of them takes position
// steps (hard translation rows, rotation limits; drives take none).
bool SixDofHasRowsBesideGroups(const ConstraintPlan& c) {
  const SixDofConfig& config = c.six_dof;
  return (!config.translation_point &&
          (config.translation_rows || config.has_translation_drives())) ||
         (!config.rotation_euler && (config.rotation_limits || c.has_rotation_drives()));
}
bool SixDofRowsBesideGroupsTakePositionSteps(const SixDofConfig& config) {
  bool hard_translation = false;
  for (int i = 0; i < 3; ++i) {
    hard_translation |= config.translation_rows &&
                        config.translation[i] != AxisLimitKind::kFree &&
                        !config.translation_soft[i];
  }
  return hard_translation || (!config.rotation_euler && config.rotation_limits);
}

}  // namespace

bool ExactSolvePlan::SolvedWhole(const ConstraintPlan& c) {
  // Called per constraint and pass by the step: no GroupsOf (it allocates).
  switch (c.type) {
    case ConstraintType::kPulley: case ConstraintType::kPath: return true;
    case ConstraintType::kDistance: return !c.rod_group;
    case ConstraintType::kSixDof:
      return !c.six_dof.translation_point && !c.six_dof.rotation_euler;
    default: return false;
  }
}

namespace {

// The groups attached to each dynamic body, as (group, is body2).
using Attachments = std::vector<std::vector<std::pair<std::size_t, bool>>>;

// A dynamic body with all six DOFs (what a constraint with row groups needs
// on one side).
bool FreeBody(const Scene& scene, std::size_t body, MotionType motion) {
  return motion == MotionType::kDynamic && scene.bodies()[body].allowed_dofs == AllowedDofs::kAll;
}

// The two ends of a constraint in the solve, ordered: its dynamic bodies,
// with static and kinematic ones as one fixed frame (neither moves).
std::pair<std::size_t, std::size_t> SolvedEnds(const StepPlan& plan, const ConstraintPlan& c) {
  const std::size_t fixed_frame = plan.bodies.size();
  const std::size_t a = c.motion1 == MotionType::kDynamic ? c.body1 : fixed_frame;
  const std::size_t b = c.motion2 == MotionType::kDynamic ? c.body2 : fixed_frame;
  return std::minmax(a, b);
}

std::string Unavailable(const Scene& scene, const StepPlan& plan) {
  // A body whose allowed DOFs lock some axes moves only along the others
  // (K counts its mass and inertia there only). A constraint with row groups
  // needs one dynamic body with all six: between a restricted body and a
  // fixed frame or another restricted body, rows along the locked axes (a
  // planar hinge's out-of-plane rows) move nothing, and K is singular.
  for (const ConstraintPlan& c : plan.constraints) {
    if (ExactSolvePlan::SolvedWhole(c) || FreeBody(scene, c.body1, c.motion1) ||
        FreeBody(scene, c.body2, c.motion2)) {
      continue;
    }
    return c.label + " joins no dynamic body with all six degrees of freedom (" +
           plan.bodies[c.body1].label + ", " + plan.bodies[c.body2].label +
           "): the rows along the axes their allowed_dofs lock move nothing, which the "
           "exact solve cannot factor";
  }
  // Two constraints between the same two bodies (static and kinematic
  // bodies count as one fixed frame: neither moves in the solve) have
  // dependent rows: two ball joints leave the turn about the line through
  // their anchors free, and equal and opposite impulses along that line move
  // nothing, so K is singular and float would factor it into arbitrary
  // impulses.
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> joined;
  for (std::size_t i = 0; i < plan.constraints.size(); ++i) {
    const ConstraintPlan& c = plan.constraints[i];
    if (ExactSolvePlan::SolvedWhole(c)) continue;  // none of its rows is in K
    const auto [it, first] = joined.emplace(SolvedEnds(plan, c), i);
    if (!first) {
      const ConstraintPlan& other = plan.constraints[it->second];
      return other.label + " and " + c.label +
             " join the same two bodies (static and kinematic bodies count as one fixed "
             "frame): their rows are dependent, which the exact solve cannot factor; a "
             "hinge or fixed constraint (Gauss-Seidel) holds such a pair";
    }
  }
  return {};
}

}  // namespace

void ChooseRodGroups(const Scene& scene, StepPlan& plan) {
  std::set<std::pair<std::size_t, std::size_t>> joined;
  for (const ConstraintPlan& c : plan.constraints) {
    if (c.type == ConstraintType::kDistance || ExactSolvePlan::SolvedWhole(c)) continue;
    joined.insert(SolvedEnds(plan, c));
  }
  for (ConstraintPlan& c : plan.constraints) {
    if (c.type != ConstraintType::kDistance || !c.rod) continue;
    if (!FreeBody(scene, c.body1, c.motion1) && !FreeBody(scene, c.body2, c.motion2)) continue;
    c.rod_group = joined.insert(SolvedEnds(plan, c)).second;
  }
}

ExactSolvePlan PlanExactSolve(const Scene& scene, const StepPlan& plan) {
  ExactSolvePlan exact;
  exact.unavailable = Unavailable(scene, plan);
  if (!exact.available()) return exact;

  std::vector<ExactSolvePlan::Group> groups;  // in scene order
  Attachments attached(plan.bodies.size());
  for (std::size_t i = 0; i < plan.constraints.size(); ++i) {
    const ConstraintPlan& c = plan.constraints[i];
    for (ExactRows rows : GroupsOf(c)) {
      const std::size_t g = groups.size();
      groups.push_back({i, rows});
      if (c.motion1 == MotionType::kDynamic) attached[c.body1].push_back({g, false});
      if (c.motion2 == MotionType::kDynamic) attached[c.body2].push_back({g, true});
    }
  }
  const std::size_t group_count = groups.size();
  for (std::size_t i = 0; i < plan.constraints.size(); ++i) {
    const ConstraintPlan& c = plan.constraints[i];
    // Swing-twist limits, the cone row and the constraints solved whole
    // always take position steps (a rod solved whole or a rigid pulley, a
    // six-DOF or path's locked axes).
    if (c.type == ConstraintType::kSwingTwist || c.type == ConstraintType::kCone ||
        ExactSolvePlan::SolvedWhole(c)) {
      exact.inequality.push_back(i);
      exact.hard_limits = true;
    } else if (c.type == ConstraintType::kSixDof) {
      if (SixDofHasRowsBesideGroups(c)) exact.inequality.push_back(i);
      exact.hard_limits |= SixDofRowsBesideGroupsTakePositionSteps(c.six_dof);
    } else if (c.type == ConstraintType::kDistance) {
      // A rod with a group: its one row is the group's.
    } else if (c.has_limits() || c.has_motor()) {  // only hinges and sliders have them here
      exact.inequality.push_back(i);
      exact.hard_limits |= c.has_limits() && !c.soft_limits;
    }
  }

  // The group graph, then symbolic elimination by minimum degree: eliminating
  // a group joins its remaining neighbours into a clique (the fill).
  std::vector<std::set<std::size_t>> adjacent(group_count);
  for (const auto& on_body : attached) {
    for (const auto& [a, a_side] : on_body) {
      for (const auto& [b, b_side] : on_body) {
        if (a != b) adjacent[a].insert(b);
      }
    }
  }
  std::vector<std::set<std::size_t>> neighbours_when_eliminated(group_count);
  std::vector<bool> eliminated(group_count, false);
  std::vector<std::size_t> position(group_count);
  std::vector<std::size_t> order;  // group (scene order) at each position
  for (std::size_t p = 0; p < group_count; ++p) {
    std::size_t best = group_count;
    for (std::size_t j = 0; j < group_count; ++j) {
      if (!eliminated[j] && (best == group_count || adjacent[j].size() < adjacent[best].size())) {
        best = j;
      }
    }
    eliminated[best] = true;
    position[best] = p;
    order.push_back(best);
    exact.order.push_back(groups[best]);
    const std::set<std::size_t> remaining = adjacent[best];
    neighbours_when_eliminated[best] = remaining;
    for (std::size_t a : remaining) {
      adjacent[a].erase(best);
      for (std::size_t b : remaining) {
        if (a != b) adjacent[a].insert(b);
      }
    }
  }

  // Blocks in positions: every (p, later neighbour) pair, numbered once (a
  // map: as many entries as blocks, not groups squared).
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> block_of;
  const auto block = [&](std::size_t first, std::size_t second) {
    const auto [it, added] = block_of.emplace(std::pair(first, second), exact.blocks.size());
    if (added) exact.blocks.push_back({first, second});
    return it->second;
  };
  exact.later.resize(group_count);
  exact.updates.resize(group_count);
  for (std::size_t p = 0; p < group_count; ++p) {
    std::vector<std::size_t> later;
    for (std::size_t j : neighbours_when_eliminated[order[p]]) later.push_back(position[j]);
    std::sort(later.begin(), later.end());
    for (std::size_t q : later) exact.later[p].push_back({q, block(p, q)});
  }
  for (std::size_t p = 0; p < group_count; ++p) {
    const auto& later = exact.later[p];
    for (std::size_t l = 0; l < later.size(); ++l) {
      for (std::size_t r = l; r < later.size(); ++r) {
        const std::size_t target = l == r ? ExactSolvePlan::kDiagonal
                                          : block(later[l].position, later[r].position);
        exact.updates[p].push_back({l, r, target});
      }
    }
  }

  for (std::size_t body = 0; body < attached.size(); ++body) {
    const auto& on_body = attached[body];
    for (std::size_t a = 0; a < on_body.size(); ++a) {
      for (std::size_t b = a + 1; b < on_body.size(); ++b) {
        auto first = on_body[a], second = on_body[b];
        if (position[first.first] > position[second.first]) std::swap(first, second);
        const std::size_t p = position[first.first], q = position[second.first];
        exact.shared_bodies.push_back({body, p, q, first.second, second.second, block(p, q)});
      }
    }
  }
  return exact;
}

}  // namespace manyworlds
