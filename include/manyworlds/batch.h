// A batch: N copies of one scene, stepped together, one SIMD lane per world.
//
//   Scene scene = ...;                       // bodies and constraints
//   Batch batch(scene, 4096);                // 4096 worlds, all cores
//   batch.SetForce(world, body, {1, 0, 0});  // actions, per world
//   batch.Step(StepSettings{});              // one step of every world
//   batch.GetState(states);                  // observations
//
// Every world runs exactly the scalar Gauss-Seidel sweep of Jolt's solver
// (spec 4.1) for its own data; worlds never interact, and a world's result
// does not depend on its lane, its block, the thread count or its neighbours.
//
// Threads: a Batch spreads its own Step over threads, but is not itself
// thread-safe: call one Batch from one thread at a time (different Batches
// from different threads are fine). A call that writes or steps many worlds
// while another thread is inside such a call on the same Batch throws
// std::logic_error instead of corrupting worlds; a per-world setter or a
// read during another thread's Step throws too. A moved-from Batch throws
// std::logic_error from every call but destruction and assignment.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <stop_token>
#include <string>
#include <vector>

#include "manyworlds/scene.h"

namespace manyworlds {

// Per-world health after a Step (Batch::WorldHealth): 0 when healthy, else an
// OR of these bits. A world is unhealthy when float arithmetic broke down in
// it, never because of what its neighbours hold.
enum WorldHealthBits : std::uint8_t {
  // A position, rotation or velocity of a body is NaN or infinite (bad forces,
  // targets, states or parameters written into the world, or a blow-up).
  kNonFiniteState = 1,
  // |v|^2 or |w|^2 overflowed float in the force step (e.g. 1e30 N): Jolt's
  // velocity clamp would silently turn such a velocity into zero.
  kVelocityOverflow = 2,
  // A coordinate beyond kMaxHealthyCoordinate: float spacing there exceeds
  // 1 m, so no joint anchor can be represented any more.
  kPositionOutOfRange = 4,
  // A force, torque or motor target written into the world since the
  // previous Step was NaN or infinite and not overwritten by a finite one
  // before the Step (actions are never refused).
  kNonFiniteInput = 8,
  // Step's stop token was triggered before the world's block started: the
  // world did not step; nothing of it changed, and its forces and torques
  // still wait for the next Step.
  kNotStepped = 16,
};
inline constexpr float kMaxHealthyCoordinate = 16777216.0f;  // 2^24 m

// What Step does with the worlds it finds unhealthy (after flagging them).
enum class UnhealthyWorlds : std::uint8_t {
  kKeep,   // leave them as the step left them (they stay flagged until reset)
  kReset,  // put them back to the scene's initial state, as Reset does
};

// The accepted ranges of StepSettings (Step refuses others by name). A
// substep below a microsecond would make 1/dt and the warm-start ratio
// dt / dt_previous overflow float impulses; above a second no joint stays
// together. The iteration and substep caps bound the time one Step can take.
inline constexpr float kMinSubstepDeltaTime = 1e-6f;  // s
inline constexpr float kMaxSubstepDeltaTime = 1.0f;   // s
inline constexpr int kMaxSubsteps = 1024;
inline constexpr int kMaxIterations = 1000;  // velocity and position each
// BatchOptions::threads above this is refused (TBB cannot make such arenas).
inline constexpr int kMaxThreads = 4096;

// How a step solves the scene's joints (docs/stepping.md, "The exact solve").
enum class JointSolver : std::uint8_t {
  // Jolt's: every constraint's parts in scene order, velocity_iterations
  // then position_iterations Gauss-Seidel sweeps with Baumgarte's factor.
  kGaussSeidel,
  // Each substep solves all equality rows of a world at once, exactly (a
  // block-sparse LDL^T of J M^-1 J^T whose elimination order and fill the
  // plan fixes; ball, hinge, fixed, slider, gear, rack-and-pinion and
  // swing-twist joints, the cone's anchor, a six-DOF's all-fixed
  // translation or rotation, rigid distance constraints), with motors,
  // friction, limits, the cone's row, a six-DOF's other rows and the
  // constraints solved whole (ropes, struts and springs, pulley, path,
  // six-DOF without an all-fixed part) by block Gauss-Seidel around it
  // (velocity_iterations passes). Then, in a scene whose joints are all
  // equalities, the velocities take the normal component the joints'
  // curvature needs over the step (exact_curvature_velocity), and Newton
  // steps of the same system project the positions until every joint of
  // the world is within exact_tolerance, at most position_iterations
  // steps, no body turning more than kExactMaxNewtonTurn in one step.
  // Refused by name: two constraints with row groups between the same two
  // bodies, and a constraint with row groups that joins no dynamic body
  // with all six degrees of freedom (docs/stepping.md).
  kExact,
};
const char* JointSolverName(JointSolver solver);  // "gauss_seidel", "exact"

// kExact: the most any body turns in one Newton position step (rad). A step
// that would turn a body further is scaled down whole, direction kept (a
// trust region). Newton's linearisation of the rotation rows fails far from
// C = 0: a hinge started 90 degrees off has a row whose slope is cos 89.4
// degrees (Jolt's axis repair), and its full step turned the body by
// tens of radians, so the hinge never came back; capped, it is back within
// four Newton steps. No reference scene's step comes near the cap (their state
// digests are unchanged by it).
inline constexpr float kExactMaxNewtonTurn = 0.5f;

// kExact: the curvature correction (exact_curvature_velocity) of a world
// is weighted by 1 while, for every dynamic body, tr(G I^-1) is at most half
// of this, falling linearly to 0 at it. G = dt * sum over the body's ball
// anchors of max(0, pull) (E - r^ r^T) is the geometric stiffness of this
// step's joint impulses, and tr(G I^-1) about twice the sum of (omega dt)^2
// over the transverse swings those pulls drive. The correction is explicit
// in that swing, which explicit steps follow only for omega dt < 2
// (Stormer-Verlet's bound): at weight 1 omega dt stays below about 1.4.
// Heavier pulls (chain16-r100 and -r1000) are left to the implicit
// velocity solve and the Newton projection, which damp them.
inline constexpr float kExactCurvatureTransverseLimit = 4.0f;

// Jolt's PhysicsSettings that matter to constraint-only worlds (spec 4.2).
struct StepSettings {
  float delta_time = 1.0f / 60.0f;  // s, of the whole step
  int substeps = 1;                 // Jolt's collision steps: dt / substeps each
  int velocity_iterations = 10;
  int position_iterations = 2;
  // Opt-in (0, the default: Jolt's passes, every one of velocity_iterations):
  // a world stops its Gauss-Seidel velocity passes after the first pass
  // that changed no velocity component of any of its dynamic bodies by
  // more than this (m/s for linear, rad/s for angular velocity), MuJoCo's
  // solver tolerance in spirit. Each world stops on its own, with the same
  // bits whatever its neighbours do; a block's passes end once every world
  // in it has stopped, which is where the time is saved (docs/stepping.md,
  // "Velocity tolerance"). With kExact: the block Gauss-Seidel passes
  // around the joints' exact solve (motors, limits, contacts).
  float velocity_tolerance = 0.0f;
  float baumgarte = 0.2f;
  bool warm_start = true;
  Float3 gravity{0.0f, -9.81f, 0.0f};
  UnhealthyWorlds unhealthy_worlds = UnhealthyWorlds::kKeep;
  // Opt-in remedy (off: Jolt's integration, bit for bit): Euler's gyroscopic
  // term -w x (I w) for dynamic bodies, by an energy-keeping implicit midpoint
  // step before the forces of every substep (kernels/integration-inl.h,
  // reference/gyroscopic.h). Jolt leaves it out, so a body spun about its
  // intermediate axis never flips (docs/stability.md).
  bool gyroscopic = false;
  JointSolver solver = JointSolver::kGaussSeidel;
  // kExact: a world's Newton position steps stop once every row group's
  // error is at most this (m for anchors and slider lines, rad for rotations
  // and couplings); velocity_iterations (the block Gauss-Seidel passes),
  // baumgarte (the limits' position steps) and warm_start (the bounded rows')
  // are used only by motors, friction and limits.
  float exact_tolerance = 1e-5f;
  // kExact: how much of the joints' geometric stiffness the velocity solve
  // takes implicitly, as a multiple of the backward-Euler amount (1). It
  // keeps light links under a heavy pull from swinging past what one step
  // can follow (chain16-r100 holds at 1 substep with 4 Newton steps,
  // chain16-r1000 with 30); larger values damp more and let the heavy
  // chains hold with fewer Newton steps; 0 is off.
  float exact_geometric_stiffness = 1.0f;
  // kExact, in scenes whose constraints all have only equality rows (no
  // motor, friction, limit, cone, spring, rope, strut, path, no six-DOF
  // beyond its all-fixed parts, no rod solved whole, no contact): after the
  // integration, add to the velocities the normal velocity the joints'
  // curvature needs over the step, SHAKE's first chord
  // step with the velocity solve's J and factors of K (weighted by
  // kExactCurvatureTransverseLimit). Without it the next velocity solve
  // removes that component, which loses energy at first order in dt:
  // chain16 released from horizontal loses 1.15 % of M g L in its first
  // second, 0.47 % with it (docs/stepping.md). false: the positions'
  // Newton projection alone.
  bool exact_curvature_velocity = true;
  // Contacts (Jolt's PhysicsSettings, docs/contacts.md): shapes closer than
  // the speculative distance make contact points; up to the slop a
  // penetration is left alone; a position step corrects at most
  // max_penetration_distance of it; an approach slower than
  // min_velocity_for_restitution does not bounce.
  float speculative_contact_distance = 0.02f;  // m
  float penetration_slop = 0.02f;              // m
  float max_penetration_distance = 0.2f;       // m
  float min_velocity_for_restitution = 1.0f;   // m/s
  // Off (Jolt): a contact is found once shapes are within the speculative
  // distance, so a body faster than that per substep lands inside what it
  // hits by up to one substep's travel, and keeps what the slop leaves. On:
  // each slot's distance grows by how far its shapes may approach in the
  // substep (their relative speed along the normal, plus spin times reach),
  // so they land on the surface (docs/contacts.md).
  bool speculative_contacts_from_velocity = false;
};

// A world's constraint position error split by unit (Batch::MaxConstraintErrorSplit).
struct ConstraintErrorSplit {
  double linear = 0.0;   // m: rows that hold points together or on an axis, linear limits
  double angular = 0.0;  // rad: rows that hold rotations, angular limits, gear and rack couplings
};

struct BatchOptions {
  int threads = 0;  // 0: every core TBB sees; at most kMaxThreads
  // Blocks of 16 worlds per TBB task; 0 picks enough tasks for the threads.
  std::size_t blocks_per_task = 0;
  // Highway target bit (e.g. HWY_AVX2, HWY_SCALAR) to run instead of the best
  // one this CPU supports; 0 dispatches. For SIMD-efficiency benchmarks and
  // per-target tests; an unsupported target is refused. Affects this Batch
  // only (Highway's global dispatch is never changed).
  std::int64_t target = 0;
  // Time every phase of every block's step (Batch::GetPhaseProfile): a
  // steady_clock read after each phase of each block and substep, about
  // 10 % of cartpole's step and nothing measurable on larger scenes (the
  // results keep every bit).
  bool profile_phases = false;
};

// The phases of a block's step (batch/step_kernels.cc), in order, each
// substep: the forces (gravity, damping, velocity clamps), every constraint's
// setup, warm start, the velocity iterations, integration, the position
// iterations; then, once per step, the finish (forces cleared, health).
enum class StepPhase : std::uint8_t {
  kForces,
  kSetup,
  kWarmStart,
  kVelocity,
  kIntegration,
  kPosition,
  kFinish,
};
inline constexpr std::size_t kStepPhaseCount = 7;
const char* StepPhaseName(StepPhase phase);  // "forces", "setup", "warm_start", ...

// Where the steps' time went (BatchOptions::profile_phases): thread time
// per phase summed over every block stepped since the Batch was made or
// ResetPhaseProfile, and how many blocks (of 16 worlds) and real worlds
// those were. seconds[p] / world_steps is a phase's cost per world-step.
struct PhaseProfile {
  std::array<double, kStepPhaseCount> seconds{};
  std::uint64_t block_steps = 0;
  std::uint64_t world_steps = 0;
};

// Every world of a Batch exactly as it is (Batch::Snapshot): bodies, per-world
// parameters and targets, the solver's warm-start impulses and caches, health
// and the previous step size. Restoring it makes every world continue bit for
// bit as the original would. Its bytes can be stored and read back with
// FromBytes; they fit only a Batch of the same scene, world count and build of
// the library on the same kind of machine (Restore checks, by name).
class BatchSnapshot {
 public:
  BatchSnapshot() = default;
  bool empty() const { return data_.empty(); }
  std::size_t world_count() const;
  std::span<const std::byte> bytes() const { return data_; }
  // Refuses (std::invalid_argument) bytes that are not a whole snapshot.
  static BatchSnapshot FromBytes(std::span<const std::byte> bytes);

 private:
  friend class Batch;
  std::vector<std::byte> data_;
};

// The 13 numbers of one body's state, in this order, in every state array.
inline constexpr std::size_t kStateFloatsPerBody = 13;
enum class StateField : std::uint8_t {
  kPosition,         // 3: centre of mass, world (offset 0)
  kRotation,         // 4: quaternion x, y, z, w (offset 3)
  kLinearVelocity,   // 3 (offset 7)
  kAngularVelocity,  // 3 (offset 10)
};
std::size_t StateFieldOffset(StateField field);
std::size_t StateFieldSize(StateField field);

// An action written by Step(settings, io) inside the step's own pass: into
// each block just before it steps, by the task that steps it (written from
// the calling thread instead, half of the blocks would be stepped by the
// other core from the caller's cache). Bit for bit the separate call named,
// made before the Step, with its checks and its notes of non-finite values
// (reported in WorldHealth after the step, as for the separate call).
enum class ActionKind : std::uint8_t {
  kForce,           // SetForces(body, per_world): [world][3], N, world space
  kTorque,          // SetTorques(body, per_world): [world][3], N m, world space
  kTargetVelocity,  // SetTargetVelocities(constraint, per_world): [world]
  kTargetPosition,  // SetTargetPositions(constraint, per_world): [world]
  // Drives of swing-twist and six-DOF constraints (per axis):
  kTargetOrientation,      // SetTargetOrientations: [world][4] quaternion x, y, z, w
  kTargetAngularVelocity,  // SetTargetAngularVelocities: [world][3] rad/s
  kTargetTranslation,      // SetTargetTranslations (six-DOF): [world][3] m
  kTargetLinearVelocity,   // SetTargetLinearVelocities (six-DOF): [world][3] m/s
};
struct StepAction {
  ActionKind kind;
  std::size_t index;  // the body (forces, torques) or the constraint (targets)
  std::span<const float> per_world;
};

// What one Batch::Step(settings, io) does besides stepping, block by block
// in the step's own pass (on the step's threads, while each block of 16
// worlds is in cache): an RL loop's actions, its resets of done worlds and
// its reads of observations, which as separate calls pass over every block
// again (on two threads from the other core's cache). Every span is
// optional (empty:
// not done); a non-empty one must have exactly the size given, or the call
// throws std::invalid_argument naming it before anything is written or
// stepped (an action the separate call would refuse throws as it does:
// SceneError for a static body or a constraint without a single motor,
// std::out_of_range for an index). Per block, in this order:
//   0. write the actions, in the order given (StepAction above);
//   1. step the block (health flags and StepSettings::unhealthy_worlds as
//      in a plain Step);
//   2. reset the worlds with reset_mask[world] != 0 to the scene's initial
//      state, as Reset (health and pending-input notes cleared), or, with
//      reset_states, as ResetTo (a zero rotation in a masked world's rows is
//      refused up front);
//   3. write the outputs from the worlds as they are now.
// The results are bit for bit those of the actions' separate calls;
// Step(settings, stop); Reset(mask) or ResetTo(mask, states);
// GetState(state_out); GetJointCoordinates(joints_out). Resetting after the step is what
// Gymnasium's and EnvPool's autoreset needs: pass the worlds that were done
// after the previous step; their action of this step is wasted, and the
// observation written for them is their new episode's first (the initial
// state). A block a stop request left unstepped (kNotStepped) gets its
// actions (for its next step, as with the separate calls) but is not reset;
// its outputs are written.
struct StepIo {
  std::span<const StepAction> actions;       // written before each block steps
  std::span<const std::uint8_t> reset_mask;  // [world], or empty: no resets
  std::span<const float> reset_states;       // [world][body][13]; needs reset_mask
  std::span<float> state_out;                // [world][body][13] (GetState)
  std::span<float> joints_out;  // [world][JointCoordinatesPerWorld()] (GetJointCoordinates)
};

class Batch {
 public:
  // Throws SceneError naming the body or constraint and field of a bad scene.
  Batch(const Scene& scene, std::size_t world_count, BatchOptions options = {});
  ~Batch();
  Batch(Batch&&) noexcept;
  Batch& operator=(Batch&&) noexcept;

  std::size_t world_count() const;
  std::size_t body_count() const;
  std::size_t constraint_count() const;
  const Scene& scene() const;

  // Steps every world by settings.delta_time. Throws SceneError (naming the
  // field and the accepted range) for settings outside the ranges above.
  void Step(const StepSettings& settings);
  // The same, interruptible: once `stop` is requested, blocks of 16 worlds
  // not yet started are left exactly as they were and flagged kNotStepped;
  // blocks already started finish their step. Returns whether every world
  // stepped.
  bool Step(const StepSettings& settings, std::stop_token stop);
  // Step with the resets and observation reads of an RL loop done inside
  // the step's pass over each block (StepIo above). Returns as Step(stop).
  bool Step(const StepSettings& settings, const StepIo& io, std::stop_token stop = {});
  // Throws exactly what Step(settings, io) would throw for these arguments
  // (io's sizes and actions, then the settings; also std::logic_error during
  // another thread's call), and changes nothing: for callers
  // that must know every step will be accepted before any steps (ShardedBatch
  // checks every MPI rank's step this way before one rank steps).
  void CheckStep(const StepSettings& settings, const StepIo& io = {}) const;

  // ---- state, world-major: [world][body][13] (see StateField)
  void GetState(std::span<float> out) const;
  // Writes every world, or only those with mask[world] != 0. Rotations are
  // normalised unless already unit to float rounding (then kept bit for bit,
  // so SetState(GetState()) changes no bit); velocities of static bodies stay
  // zero. Non-finite values are written as given (the next Step flags the
  // world, see WorldHealth); a zero rotation is refused before anything is
  // written. Solver state (warm-start impulses) is not part of a state array:
  // Snapshot/Restore carry everything.
  void SetState(std::span<const float> in, std::span<const std::uint8_t> world_mask = {});
  // One field of every world and body: [world][body][StateFieldSize(field)].
  void GetField(StateField field, std::span<float> out) const;
  // One world's state, [body][13]: the same bits as its rows of GetState,
  // without reading every world (a recorder of a few worlds, a debugger).
  void GetWorldState(std::size_t world, std::span<float> out) const;
  void SetField(StateField field, std::span<const float> in);

  // ---- solver state of one world: what its constraints and contact slots
  // carry from one step to the next besides the bodies (Jolt's SaveState /
  // RestoreState): the accumulated impulses that warm-start the next step,
  // the hinges' turn counts, the directions distance, pulley and cone
  // constraints remember, and the contacts' kept points. SolverStateSize()
  // floats, constraints in scene order then contact slots, each as
  // docs/stepping.md ("Solver state of one world") lists; rows a constraint does not have
  // read 0. reference::World::SolverState uses the same layout.
  std::size_t SolverStateSize() const;
  void GetSolverState(std::size_t world, std::span<float> out) const;
  // Refuses (std::invalid_argument naming the constraint or contact, the
  // value and its index) before writing anything: a wrong size, a value that
  // is not finite, a non-zero value for a row the constraint does not have, a
  // contact point's kept flag other than 0 or 1.
  void SetSolverState(std::size_t world, std::span<const float> in);

  // Back to the scene's initial state (state, accumulated impulses, motor
  // targets and per-world overrides) in the worlds with mask[world] != 0.
  void Reset(std::span<const std::uint8_t> world_mask);
  // Like Reset, then the given state ([world][body][13], every world's slot
  // present, only masked worlds read).
  void ResetTo(std::span<const std::uint8_t> world_mask, std::span<const float> state);

  // ---- joint coordinates (observations), from the bodies as they are now:
  // per constraint, [world][JointCoordinateCount(c)], in the order of
  // JointCoordinateNames(c): hinge angle, unwrapped_angle (continuous over
  // turns) and angular_velocity; slider position and velocity; distance;
  // swing-twist and six-DOF angles, translations and rates; path fraction
  // (batch/joint_coordinates.h lists every type). The all-constraints form
  // writes [world][JointCoordinatesPerWorld()], constraints in scene order.
  std::size_t JointCoordinateCount(std::size_t constraint) const;
  std::vector<std::string> JointCoordinateNames(std::size_t constraint) const;
  void GetJointCoordinates(std::size_t constraint, std::span<float> out) const;
  std::size_t JointCoordinatesPerWorld() const;
  void GetJointCoordinates(std::span<float> out) const;
  // One world's row of GetJointCoordinates(out): [JointCoordinatesPerWorld()].
  void GetWorldJointCoordinates(std::size_t world, std::span<float> out) const;
  // The force (N) or torque (N m) each motor or friction row of a constraint
  // applied in the last substep of the last Step, [world][MotorForceCount(c)]:
  // 1 for a hinge, slider or path drive, 3 for swing-twist rotation drives
  // (twist, swing_y, swing_z), 6 for six-DOF (X, Y, Z, then rotations); 0
  // where an axis has none. Energy a motor used: torque * angular velocity * dt.
  std::size_t MotorForceCount(std::size_t constraint) const;
  void GetMotorForces(std::size_t constraint, std::span<float> out) const;

  // ---- contacts (docs/contacts.md): one slot per pair of shapes that may
  // touch, in solve order. GetContacts writes [world][ContactSlotCount()]
  // [kContactFloats]: per slot the points the last substep kept (0 to
  // max_points), the normal force (N, >= 0: the normal impulses over the
  // substep), the whole contact force on body 2 (N, world space: normal and
  // friction; body 1 gets its negation) and the normal from body 1 to body
  // 2; all zero where the shapes do not touch, and before the first Step.
  struct ContactSlot {
    std::size_t body1, body2;  // body1 < body2
    std::size_t max_points;
  };
  static constexpr std::size_t kContactFloats = 8;  // points, normal force, force xyz, normal xyz
  std::size_t ContactSlotCount() const;
  ContactSlot GetContactSlot(std::size_t slot) const;
  void GetContacts(std::span<float> out) const;

  // ---- exact checkpoints (tree search, resets to saved states, replay)
  BatchSnapshot Snapshot() const;
  // Every world (empty mask), or only the worlds with mask[world] != 0, back
  // to the snapshot, bit for bit. The step size the snapshot was taken after
  // (for Jolt's warm-start ratio) is restored with every world only: a masked
  // restore keeps the batch's own, which the next Step uses for all worlds.
  // Throws std::invalid_argument, changing nothing, for a snapshot of
  // another scene, world count or layout.
  void Restore(const BatchSnapshot& snapshot, std::span<const std::uint8_t> world_mask = {});

  // ---- actions, per world. Forces and torques (world space, through the
  // centre of mass) act during the next Step and are then cleared, as Jolt's
  // AddForce. The span forms take [world][body][3].
  void SetForce(std::size_t world, std::size_t body, Float3 force);
  void SetTorque(std::size_t world, std::size_t body, Float3 torque);
  void SetForces(std::span<const float> forces);
  void SetTorques(std::span<const float> torques);
  // One body in every world: per_world holds [world][3]. The cheap form for
  // RL actions (no per-call checks, lanes written directly).
  void SetForces(std::size_t body, std::span<const float> per_world);
  void SetTorques(std::size_t body, std::span<const float> per_world);

  // Motor targets of a hinge (rad/s, rad) or slider (m/s, m), per world.
  // Position targets are clamped into the limits as Jolt does.
  void SetTargetVelocity(std::size_t world, std::size_t constraint, float velocity);
  void SetTargetPosition(std::size_t world, std::size_t constraint, float position);
  void SetTargetVelocities(std::size_t constraint, std::span<const float> per_world);
  void SetTargetPositions(std::size_t constraint, std::span<const float> per_world);
  // Rotation drives of a swing-twist or six-DOF constraint: the orientation
  // of body 2's constraint frame in body 1's (normalised here, clamped into
  // the limits each step; a zero quaternion is refused) and the angular
  // velocity about body 2's frame axes X, Y, Z (rad/s).
  void SetTargetOrientation(std::size_t world, std::size_t constraint, Quaternion orientation);
  void SetTargetAngularVelocity(std::size_t world, std::size_t constraint,
                                Float3 angular_velocity);
  // Translation drives of a six-DOF constraint, in body 1's constraint frame:
  // the target displacement (m) and velocity (m/s) per axis.
  void SetTargetTranslation(std::size_t world, std::size_t constraint, Float3 translation);
  void SetTargetLinearVelocity(std::size_t world, std::size_t constraint, Float3 velocity);
  // The same for every world at once: [world][4] orientations (a zero
  // quaternion in any world is refused, naming it, before anything is
  // written) and [world][3] velocities and translations.
  void SetTargetOrientations(std::size_t constraint, std::span<const float> per_world);
  void SetTargetAngularVelocities(std::size_t constraint, std::span<const float> per_world);
  void SetTargetTranslations(std::size_t constraint, std::span<const float> per_world);
  void SetTargetLinearVelocities(std::size_t constraint, std::span<const float> per_world);

  // ---- per-world parameters (domain randomisation); the scene's values are
  // the defaults, and a parameter nobody overrides costs nothing extra.
  void SetMassProperties(std::size_t world, std::size_t body, float mass,
                         Float3 inertia_diagonal);
  void SetDamping(std::size_t world, std::size_t body, float linear, float angular);
  void SetGravityFactor(std::size_t world, std::size_t body, float factor);
  // Limits of a hinge, slider or distance constraint; a rigid distance
  // (DistanceConstraintSettings::rigid) takes min == max only (it stays a
  // rod; the exact solve factors its row).
  void SetLimits(std::size_t world, std::size_t constraint, float min, float max);
  void SetLimitsSpring(std::size_t world, std::size_t constraint, float frequency_or_stiffness,
                       float damping);
  void SetMotorSpring(std::size_t world, std::size_t constraint, float frequency_or_stiffness,
                      float damping);
  void SetMotorLimits(std::size_t world, std::size_t constraint, float min, float max);
  void SetMaxFriction(std::size_t world, std::size_t constraint, float max_friction);
  void SetRatio(std::size_t world, std::size_t constraint, float ratio);

  // ---- reports
  // The plan: which kernels run in which phase, per constraint, with storage,
  // for the given step settings (by default those of the last Step).
  std::string Plan() const;
  std::string Plan(const StepSettings& settings) const;
  // Bytes stored per world: state, parameters and solver state (what a
  // step recomputes is in one scratch per thread, not per world).
  std::size_t BytesPerWorld() const;
  const char* SimdTarget() const;     // Highway's name of the dispatched target
  std::size_t SimdLanes() const;      // floats per vector on it
  int threads() const;

  // Health of every world after the last Step, [world]: 0 or WorldHealthBits.
  // Worlds never interact: a flagged world changes no bit of any other world.
  std::span<const std::uint8_t> WorldHealth() const;

  // The phase profile (BatchOptions::profile_phases; all zero without it).
  PhaseProfile GetPhaseProfile() const;
  void ResetPhaseProfile();
  std::size_t UnhealthyWorldCount() const;

  // The largest position error of any constraint in a world after the last
  // step (m for linear rows, rad for angular rows), for accuracy reports.
  float MaxConstraintError(std::size_t world) const;
  // The same two units apart: the largest linear error (m) and the largest
  // angular error (rad) of any constraint in a world after the last step;
  // MaxConstraintError is the larger of the two (batch/constraint_error.h
  // lists which rows are which).
  ConstraintErrorSplit MaxConstraintErrorSplit(std::size_t world) const;
  // The position error of one constraint of a world (as above), and the
  // velocity residual |J v| of its equality rows (m/s for linear rows, rad/s
  // for angular rows; limits, motors and friction excluded): see
  // batch/constraint_error.h for each constraint type.
  double ConstraintError(std::size_t world, std::size_t constraint) const;
  double ConstraintVelocityError(std::size_t world, std::size_t constraint) const;

  class Impl;

 private:
  // impl_, or std::logic_error for a moved-from Batch or a call during
  // another thread's Step.
  Impl& impl();
  const Impl& impl() const;
  std::unique_ptr<Impl> impl_;
};

}  // namespace manyworlds
