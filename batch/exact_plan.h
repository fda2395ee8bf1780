// The plan of the exact joint solve (JointSolver::kExact): which sparse
// system every block factors, in which order, with which fill.
//
// The unknowns are the impulses of the scene's ball joints (three rows each).
// Two joints couple in K = J M^-1 J^T when they share a dynamic body; static
// and kinematic bodies have infinite mass and couple nothing. All worlds have
// the scene's joint graph, so the elimination order (greedy minimum degree,
// ties by scene order) and the fill it causes are decided here once, and
// every block factors its 16 lanes with the same instructions: a chain or a
// tree eliminates leaf first with no fill at all; a closed loop adds a few
// off-diagonal blocks. Everything is in positions of the elimination order.
#pragma once

#include <cstddef>
#include <string>
#include <vector>


namespace manyworlds {

class Scene;
struct StepPlan;

struct ExactSolvePlan {
  // Why the scene cannot be solved exactly (names the constraint or body);
  // empty when it can.
  std::string unavailable;

  // The plan's constraint index of the joint eliminated at each position.
  std::vector<std::size_t> order;

  // Off-diagonal block `block` couples positions first < second (rows of
  // `first`, columns of `second`).
  struct Block {
    std::size_t first, second;
  };
  std::vector<Block> blocks;  // couplings and fill

  // The terms of K's off-diagonal blocks: joints at positions first < second
  // share the dynamic body `body`; each is that body's body1 (sign -1 in J)
  // or body2 (+1).
  struct SharedBody {
    std::size_t body;
    std::size_t first, second;
    bool first_is_body2, second_is_body2;
    std::size_t block;
  };
  std::vector<SharedBody> shared_bodies;

  // Eliminating position p updates, for each pair of its later neighbours
  // (i <= j, as positions), K_ij -= K_ip K_pp^-1 K_pj: `target` is block
  // index of (i, j), or kDiagonal when i == j (then K_ii).
  static constexpr std::size_t kDiagonal = static_cast<std::size_t>(-1);
  struct Neighbour {
    std::size_t position;  // later in the order than p
    std::size_t block;     // the block (p, position)
  };
  struct Update {
    std::size_t left, right;  // indices into p's neighbours, left <= right
    std::size_t target;       // block index, or kDiagonal
  };
  std::vector<std::vector<Neighbour>> later;   // per position
  std::vector<std::vector<Update>> updates;    // per position

  bool available() const { return unavailable.empty(); }
  std::size_t joint_count() const { return order.size(); }
  std::size_t fill_blocks() const;  // blocks that are fill, not couplings
};

// Plans the exact solve of a scene CompilePlan has laid out as `plan`; a
// scene it cannot solve gets `unavailable` (not an exception). Storage grows
// with the blocks (couplings and fill), time with joints squared (the
// minimum-degree search).
ExactSolvePlan PlanExactSolve(const Scene& scene, const StepPlan& plan);

}  // namespace manyworlds
