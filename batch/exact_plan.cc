// Elimination order and fill of the exact joint solve (batch/exact_plan.h).

#include "batch/exact_plan.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "batch/plan.h"
#include "manyworlds/scene.h"

namespace manyworlds {

std::size_t ExactSolvePlan::fill_blocks() const {
  std::set<std::size_t> coupled;
  for (const SharedBody& shared : shared_bodies) coupled.insert(shared.block);
  return blocks.size() - coupled.size();
}

namespace {

// The joints attached to each dynamic body, as (joint, is body2).
using Attachments = std::vector<std::vector<std::pair<std::size_t, bool>>>;

std::string Unavailable(const Scene& scene, const StepPlan& plan) {
  for (std::size_t i = 0; i < plan.constraints.size(); ++i) {
    const ConstraintPlan& c = plan.constraints[i];
    if (c.type != ConstraintType::kPoint) {
      return c.label + " is a " + ConstraintTypeName(c.type) +
             " constraint; the exact solve takes point constraints (ball joints) only";
    }
  }
  for (std::size_t b = 0; b < plan.bodies.size(); ++b) {
    if (plan.bodies[b].motion == MotionType::kDynamic &&
        scene.bodies()[b].allowed_dofs != AllowedDofs::kAll) {
      return plan.bodies[b].label +
             " restricts its allowed_dofs; the exact solve takes unrestricted bodies only";
    }
  }
  // Two ball joints between the same two bodies (static and kinematic
  // bodies count as one fixed frame: neither moves in the solve) leave the
  // turn about the line through their anchors free and make their rows
  // dependent: equal and opposite impulses along that line move nothing, so
  // K is singular and float would factor it into arbitrary impulses.
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> joined;
  const std::size_t kFixedFrame = plan.bodies.size();
  for (std::size_t i = 0; i < plan.constraints.size(); ++i) {
    const ConstraintPlan& c = plan.constraints[i];
    const std::size_t a = c.motion1 == MotionType::kDynamic ? c.body1 : kFixedFrame;
    const std::size_t b = c.motion2 == MotionType::kDynamic ? c.body2 : kFixedFrame;
    const auto [it, first] = joined.emplace(std::minmax(a, b), i);
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

ExactSolvePlan PlanExactSolve(const Scene& scene, const StepPlan& plan) {
  ExactSolvePlan exact;
  exact.unavailable = Unavailable(scene, plan);
  if (!exact.available()) return exact;

  const std::size_t joints = plan.constraints.size();
  Attachments attached(plan.bodies.size());
  for (std::size_t j = 0; j < joints; ++j) {
    const ConstraintPlan& c = plan.constraints[j];
    if (c.motion1 == MotionType::kDynamic) attached[c.body1].push_back({j, false});
    if (c.motion2 == MotionType::kDynamic) attached[c.body2].push_back({j, true});
  }

  // The joint graph, then symbolic elimination by minimum degree: eliminating
  // a joint joins its remaining neighbours into a clique (the fill).
  std::vector<std::set<std::size_t>> adjacent(joints);
  for (const auto& on_body : attached) {
    for (const auto& [a, a_side] : on_body) {
      for (const auto& [b, b_side] : on_body) {
        if (a != b) adjacent[a].insert(b);
      }
    }
  }
  std::vector<std::set<std::size_t>> neighbours_when_eliminated(joints);
  std::vector<bool> eliminated(joints, false);
  std::vector<std::size_t> position(joints);
  for (std::size_t p = 0; p < joints; ++p) {
    std::size_t best = joints;
    for (std::size_t j = 0; j < joints; ++j) {
      if (!eliminated[j] && (best == joints || adjacent[j].size() < adjacent[best].size())) {
        best = j;
      }
    }
    eliminated[best] = true;
    position[best] = p;
    exact.order.push_back(best);
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
  // map: as many entries as blocks, not joints squared).
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> block_of;
  const auto block = [&](std::size_t first, std::size_t second) {
    const auto [it, added] = block_of.emplace(std::pair(first, second), exact.blocks.size());
    if (added) exact.blocks.push_back({first, second});
    return it->second;
  };
  exact.later.resize(joints);
  exact.updates.resize(joints);
  for (std::size_t p = 0; p < joints; ++p) {
    std::vector<std::size_t> later;
    for (std::size_t j : neighbours_when_eliminated[exact.order[p]]) later.push_back(position[j]);
    std::sort(later.begin(), later.end());
    for (std::size_t q : later) exact.later[p].push_back({q, block(p, q)});
  }
  for (std::size_t p = 0; p < joints; ++p) {
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
