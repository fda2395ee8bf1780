// The plan of the exact joint solve (JointSolver::kExact): which sparse
// system every block factors, in which order, with which fill.
//
// The unknowns are the impulses of the scene's equality rows, in groups of
// at most three rows (ExactRows): a ball joint is one group, a hinge two (its
// point and its two rotation rows), a fixed constraint two, a slider two (its
// two translation rows and its three rotation rows), a gear or a rack and
// pinion one (a single row), a cone one (its point group; the cone row is
// bounded), a six-DOF constraint its all-fixed shortcuts (a point group when
// every translation is fixed without springs, a rotation group when every
// rotation is fixed; its other rows are bounded), a rigid distance (a rod)
// one row (ChooseRodGroups). Other distance constraints, pulley and path
// constraints, and six-DOF constraints with neither shortcut, have no group:
// all their rows are solved by Gauss-Seidel around the exact solve
// (SolvedWhole). A group of fewer than three rows is padded to
// three with rows that touch nothing (K's diagonal 1 there, impulse 0), so
// every unknown is a 3-vector and every block of K a 3x3 block.
//
// Two groups couple in K = J M^-1 J^T when they share a dynamic body; static
// and kinematic bodies have infinite mass and couple nothing. All worlds have
// the scene's graph, so the elimination order (greedy minimum degree, ties by
// scene order) and the fill it causes are decided here once, and every block
// factors its 16 lanes with the same instructions: a chain or a tree
// eliminates leaf first with no fill at all; a closed loop adds a few
// off-diagonal blocks. Everything is in positions of the elimination order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>


namespace manyworlds {

class Scene;
struct StepPlan;
struct ConstraintPlan;                     // batch/plan.h
enum class ConstraintType : std::uint8_t;  // batch/plan.h

// The kinds of row group (batch/exact_rows-inl.h has each one's J and C).
enum class ExactRows : std::uint8_t {
  kPoint,          // 3 rows: the anchors' separation (ball, hinge, fixed, swing-twist, cone,
                   //         six-DOF with every translation fixed)
  kHingeRotation,  // 2 rows: the hinge axes aligned
  kRotation,       // 3 rows: the relative rotation at rest (fixed, slider, six-DOF with
                   //         every rotation fixed)
  kSliderAxes,     // 2 rows: body 2's anchor on body 1's slider line
  kGear,           // 1 row:  theta1 + r theta2 = 0
  kRackAndPinion,  // 1 row:  theta1 - r d2 = 0
  kDistance,       // 1 row:  |p2 - p1| = the rod's length (a rigid distance)
};
int ExactRowCount(ExactRows rows);
// Whether the group's rows on body 1 (side 0) or body 2 (side 1) have a
// linear part: the rotation groups' and a gear's rows turn the bodies only,
// a rack and pinion's move only the rack (body 2). Where either of two rows
// has none, their coupling is the angular term alone (AddCoupling).
bool HasLinearRows(ExactRows rows, int side);

struct ExactSolvePlan {
  // Why the scene cannot be solved exactly (names the constraint or body);
  // empty when it can.
  std::string unavailable;

  // The group eliminated at each position: its constraint (the plan's
  // index) and which of its rows.
  struct Group {
    std::size_t constraint;
    ExactRows rows;
  };
  std::vector<Group> order;

  // The constraints with rows solved by Gauss-Seidel around the exact solve
  // (batch/exact_inequality_rows-inl.h), in scene order: the hinges and
  // sliders with motors, friction or limits, the swing-twist constraints
  // (limits, drives), the cones (the cone row), the six-DOF constraints'
  // rows beside their groups, and the constraints solved whole
  // (SolvedWhole); whether any of them takes position steps.
  std::vector<std::size_t> inequality;
  bool hard_limits = false;

  // Whether a constraint has no row group, so that the exact solve leaves
  // all its rows to Gauss-Seidel (pulley, path, distance but a rod with a
  // group, and six-DOF without an all-fixed shortcut): their rows are
  // inequalities (a rope, a strut, a pulley's length range) or soft
  // (springs), or their locked axes
  // change with the free ones (a six-DOF's fixed axes beside free ones, a
  // path), which the solve's fixed groups do not model.
  static bool SolvedWhole(const ConstraintPlan& constraint);

  // Off-diagonal block `block` couples positions first < second (rows of
  // `first`, columns of `second`).
  struct Block {
    std::size_t first, second;
  };
  std::vector<Block> blocks;  // couplings and fill

  // The terms of K's off-diagonal blocks: groups at positions first < second
  // share the dynamic body `body`; each is that body's body1 or body2 in its
  // constraint (for point groups the sign -1 or +1 of J).
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
  std::size_t group_count() const { return order.size(); }
  bool only_points() const;  // every group a point group (the chains)
  std::size_t fill_blocks() const;  // blocks that are fill, not couplings
};

// Which rigid distance constraints (ConstraintPlan::rod) have a row group:
// those with a dynamic body with all six DOFs whose two bodies (static and
// kinematic ones counting as one fixed frame) no other constraint with row
// groups, and no earlier rod with one, joins. The others are solved whole,
// as before rods had groups: a rod beside a joint between the same bodies
// could be dependent on it (K singular), and a rod on restricted bodies
// would make the scene one the exact solve refuses. Sets rod_group.
void ChooseRodGroups(const Scene& scene, StepPlan& plan);

// Plans the exact solve of a scene CompilePlan has laid out as `plan`; a
// scene it cannot solve gets `unavailable` (not an exception). Storage grows
// with the blocks (couplings and fill), time with groups squared (the
// minimum-degree search).
ExactSolvePlan PlanExactSolve(const Scene& scene, const StepPlan& plan);

}  // namespace manyworlds
