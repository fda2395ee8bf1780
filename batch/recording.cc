// Recorder (include/manyworlds/recording.h): the scene's description as
// whole arrays, the frames as growing arrays of batch/npz_writer.h. The
// arrays and their meaning are documented in docs/recording.md.

#include "manyworlds/recording.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "batch/npz_writer.h"
#include "batch/plan.h"
#include "batch/scene_checks.h"

namespace manyworlds {
namespace {

using Vec3 = std::array<double, 3>;

// q^-1 v q for a unit quaternion (x, y, z, w): a world vector in the body frame.
Vec3 RotateInverse(const Quaternion& q, const Vec3& v) {
  const double x = -q[0], y = -q[1], z = -q[2], w = q[3];
  // t = 2 (q.xyz x v); v' = v + w t + q.xyz x t
  const Vec3 t{2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])};
  return {v[0] + w * t[0] + (y * t[2] - z * t[1]), v[1] + w * t[1] + (z * t[0] - x * t[2]),
          v[2] + w * t[2] + (x * t[1] - y * t[0])};
}

// A world-space point at the scene's initial pose, in the body's COM frame.
Vec3 LocalPoint(const BodySettings& body, const Float3& p) {
  return RotateInverse(body.rotation, {double(p[0]) - body.position[0],
                                       double(p[1]) - body.position[1],
                                       double(p[2]) - body.position[2]});
}

Float3 FromWorld(const Scene& scene, std::size_t body, const Vec3& world) {
  const Vec3 local = LocalPoint(scene.bodies()[body],
                                {float(world[0]), float(world[1]), float(world[2])});
  return {float(local[0]), float(local[1]), float(local[2])};
}

// Jolt's auto-detected anchor: the inverse-mass-weighted average of the two
// centres of mass (a static body's inverse mass is 0).
Vec3 AutoDetectedPoint(const BodySettings& a, const BodySettings& b) {
  const double wa = a.motion_type == MotionType::kDynamic ? 1.0 / a.mass : 0.0;
  const double wb = b.motion_type == MotionType::kDynamic ? 1.0 / b.mass : 0.0;
  if (wa + wb == 0.0) return {a.position[0], a.position[1], a.position[2]};
  Vec3 p;
  for (int i = 0; i < 3; ++i) p[i] = (wa * a.position[i] + wb * b.position[i]) / (wa + wb);
  return p;
}

// The constraint's anchor in body 1's and body 2's COM frames: where the
// viewer draws the joint's two lines to. Gears and racks have none (the
// centres of mass); a path's is the path origin on body 1 and body 2's COM.
std::array<Float3, 2> Anchors(const Scene& scene, const ConstraintSettings& settings) {
  return std::visit(
      [&scene](const auto& s) -> std::array<Float3, 2> {
        using S = std::decay_t<decltype(s)>;
        const bool world = s.space == ConstraintSpace::kWorldSpace;
        const auto pair = [&](const Float3& p1, const Float3& p2) -> std::array<Float3, 2> {
          if (!world) return {p1, p2};
          const Vec3 w1{p1[0], p1[1], p1[2]}, w2{p2[0], p2[1], p2[2]};
          return {FromWorld(scene, s.body1, w1), FromWorld(scene, s.body2, w2)};
        };
        if constexpr (std::is_same_v<S, GearConstraintSettings> ||
                      std::is_same_v<S, RackAndPinionConstraintSettings>) {
          return {};
        } else if constexpr (std::is_same_v<S, PathConstraintSettings>) {
          if (!world) return {s.path_position, Float3{}};
          return {FromWorld(scene, s.body1, {s.path_position[0], s.path_position[1],
                                             s.path_position[2]}),
                  Float3{}};
        } else if constexpr (std::is_same_v<S, PulleyConstraintSettings>) {
          return pair(s.body_point1, s.body_point2);
        } else if constexpr (std::is_same_v<S, SixDofConstraintSettings>) {
          return pair(s.position1, s.position2);
        } else {
          if constexpr (std::is_same_v<S, FixedConstraintSettings> ||
                        std::is_same_v<S, SliderConstraintSettings>) {
            if (s.auto_detect_point) {
              const Vec3 p = AutoDetectedPoint(scene.bodies()[s.body1], scene.bodies()[s.body2]);
              return {FromWorld(scene, s.body1, p), FromWorld(scene, s.body2, p)};
            }
          }
          return pair(s.point1, s.point2);
        }
      },
      settings);
}

// A body's collision shape as recorded (docs/recording.md): the sizes its
// type uses (radius, half_height, half_extents x, y, z), the others 0; a body
// without a shape has every size and the position 0 and the rotation (0, 0,
// 0, 1), whatever its ShapeSettings hold.
struct RecordedShape {
  std::array<float, 5> size{};
  Float3 position{0, 0, 0};
  Quaternion rotation{0, 0, 0, 1};
};

RecordedShape Recorded(const ShapeSettings& shape) {
  RecordedShape r;
  switch (shape.type) {
    case ShapeType::kNone:
      return r;
    case ShapeType::kSphere:
      r.size[0] = shape.radius;
      break;
    case ShapeType::kCapsule:
      r.size[0] = shape.radius;
      r.size[1] = shape.half_height;
      break;
    case ShapeType::kBox:
      std::copy(shape.half_extents.begin(), shape.half_extents.end(), r.size.begin() + 2);
      break;
    case ShapeType::kPlane:
      break;
  }
  r.position = shape.position;
  // Normalised, as the step uses it (a scene may give any non-zero length).
  r.rotation = Normalized(shape.rotation);
  return r;
}

template <class T>
std::span<const std::byte> Bytes(const std::vector<T>& values) {
  return std::as_bytes(std::span(values));
}

std::vector<std::uint64_t> Shape(std::initializer_list<std::size_t> dims) {
  return std::vector<std::uint64_t>(dims.begin(), dims.end());
}

// numpy's '<U' array of `texts`: UTF-32LE items as wide as the longest (at
// least 1, as numpy makes an array of empty strings).
void AddTextArray(npz::StreamingNpzWriter& writer, const std::string& name,
                  const std::vector<std::string>& texts, std::vector<std::uint64_t> shape) {
  std::vector<std::vector<std::uint32_t>> codes;
  std::size_t width = 1;
  for (const std::string& text : texts) {
    codes.push_back(npz::Utf32(text));
    width = std::max(width, codes.back().size());
  }
  std::vector<std::uint32_t> items(codes.size() * width, 0);
  for (std::size_t i = 0; i < codes.size(); ++i) {
    std::copy(codes[i].begin(), codes[i].end(), items.begin() + std::ptrdiff_t(i * width));
  }
  writer.AddArray(name, "<U" + std::to_string(width), std::move(shape), Bytes(items));
}

std::vector<std::size_t> CheckedWorlds(const Batch& batch, std::span<const std::size_t> worlds) {
  if (worlds.empty()) throw std::invalid_argument("no world to record");
  std::vector<std::size_t> sorted(worlds.begin(), worlds.end());
  for (const std::size_t w : worlds) {
    if (w >= batch.world_count()) {
      throw std::invalid_argument("world " + std::to_string(w) + " out of range [0, " +
                                  std::to_string(batch.world_count()) + ")");
    }
  }
  std::sort(sorted.begin(), sorted.end());
  const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
  if (repeated != sorted.end()) {
    throw std::invalid_argument("world " + std::to_string(*repeated) + " given twice");
  }
  return {worlds.begin(), worlds.end()};
}

}  // namespace

struct Recorder::State {
  npz::StreamingNpzWriter writer;
  std::vector<std::size_t> worlds;
  std::size_t bodies = 0, constraints = 0, coordinates = 0;
  std::size_t time_array = 0, step_array = 0, position_array = 0, rotation_array = 0,
              coordinate_array = 0, health_array = 0;
  std::size_t frames = 0;
  // Reused between frames: one world's state and one frame's rows.
  std::vector<float> state, positions, rotations, coordinate_rows;
  std::vector<std::uint8_t> health;

  State(const std::string& path, const RecorderOptions& options)
      : writer(path, options.overwrite,
               options.force_zip64 ? npz::Zip64::kAlways : npz::Zip64::kWhenNeeded) {}
};

Recorder::Recorder(const Batch& batch, const std::string& path,
                   std::span<const std::size_t> worlds, const RecorderOptions& options) {
  std::vector<std::size_t> checked = CheckedWorlds(batch, worlds);
  state_ = std::make_unique<State>(path, options);
  State& s = *state_;
  npz::StreamingNpzWriter& w = s.writer;
  const Scene& scene = batch.scene();
  s.worlds = std::move(checked);
  s.bodies = batch.body_count();
  s.constraints = batch.constraint_count();
  s.coordinates = batch.JointCoordinatesPerWorld();
  const std::size_t W = s.worlds.size(), B = s.bodies, C = s.constraints, J = s.coordinates;

  w.AddArray("format_version", "<i4", Shape({1}),
             Bytes(std::vector<std::int32_t>{kRecordingFormatVersion}));
  AddTextArray(w, "scene", {options.scene}, {});
  w.AddArray("world", "<i8", Shape({W}),
             Bytes(std::vector<std::int64_t>(s.worlds.begin(), s.worlds.end())));

  std::vector<std::string> body_names;
  std::vector<std::uint8_t> motion_types, shape_types;
  std::vector<float> masses, inertia_diagonals, inertia_rotations, shape_sizes, shape_positions,
      shape_rotations;
  for (const BodySettings& body : scene.bodies()) {
    body_names.push_back(body.name);
    motion_types.push_back(static_cast<std::uint8_t>(body.motion_type));
    masses.push_back(body.mass);
    inertia_diagonals.insert(inertia_diagonals.end(), body.inertia_diagonal.begin(),
                             body.inertia_diagonal.end());
    inertia_rotations.insert(inertia_rotations.end(), body.inertia_rotation.begin(),
                             body.inertia_rotation.end());
    const RecordedShape shape = Recorded(body.shape);
    shape_types.push_back(static_cast<std::uint8_t>(body.shape.type));
    shape_sizes.insert(shape_sizes.end(), shape.size.begin(), shape.size.end());
    shape_positions.insert(shape_positions.end(), shape.position.begin(), shape.position.end());
    shape_rotations.insert(shape_rotations.end(), shape.rotation.begin(), shape.rotation.end());
  }
  AddTextArray(w, "body_name", body_names, Shape({B}));
  w.AddArray("body_motion_type", "|u1", Shape({B}), Bytes(motion_types));
  w.AddArray("body_mass", "<f4", Shape({B}), Bytes(masses));
  w.AddArray("body_inertia_diagonal", "<f4", Shape({B, 3}), Bytes(inertia_diagonals));
  w.AddArray("body_inertia_rotation", "<f4", Shape({B, 4}), Bytes(inertia_rotations));
  w.AddArray("body_shape_type", "|u1", Shape({B}), Bytes(shape_types));
  w.AddArray("body_shape_size", "<f4", Shape({B, 5}), Bytes(shape_sizes));
  w.AddArray("body_shape_position", "<f4", Shape({B, 3}), Bytes(shape_positions));
  w.AddArray("body_shape_rotation", "<f4", Shape({B, 4}), Bytes(shape_rotations));

  std::vector<std::string> names, types, coordinate_names;
  std::vector<std::int32_t> constraint_bodies, coordinate_constraints;
  std::vector<float> anchors;
  for (std::size_t c = 0; c < C; ++c) {
    const ConstraintSettings& settings = scene.constraints()[c];
    std::visit(
        [&](const auto& cs) {
          names.push_back(cs.name);
          constraint_bodies.push_back(std::int32_t(cs.body1));
          constraint_bodies.push_back(std::int32_t(cs.body2));
        },
        settings);
    types.push_back(SettingsTypeName(settings));
    for (const Float3& anchor : Anchors(scene, settings)) {
      anchors.insert(anchors.end(), anchor.begin(), anchor.end());
    }
    for (const std::string& coordinate : batch.JointCoordinateNames(c)) {
      coordinate_names.push_back((names.back().empty() ? types.back() + std::to_string(c)
                                                       : names.back()) +
                                 "/" + coordinate);
      coordinate_constraints.push_back(std::int32_t(c));
    }
  }
  AddTextArray(w, "constraint_name", names, Shape({C}));
  AddTextArray(w, "constraint_type", types, Shape({C}));
  w.AddArray("constraint_body", "<i4", Shape({C, 2}), Bytes(constraint_bodies));
  w.AddArray("constraint_anchor", "<f4", Shape({C, 2, 3}), Bytes(anchors));
  AddTextArray(w, "joint_coordinate_name", coordinate_names, Shape({J}));
  w.AddArray("joint_coordinate_constraint", "<i4", Shape({J}), Bytes(coordinate_constraints));

  s.time_array = w.AddGrowingArray("time", "<f8", 8, {});
  s.step_array = w.AddGrowingArray("step", "<i8", 8, {});
  s.position_array = w.AddGrowingArray("position", "<f4", 4, Shape({W, B, 3}));
  s.rotation_array = w.AddGrowingArray("rotation", "<f4", 4, Shape({W, B, 4}));
  s.coordinate_array = w.AddGrowingArray("joint_coordinates", "<f4", 4, Shape({W, J}));
  s.health_array = w.AddGrowingArray("health", "|u1", 1, Shape({W}));
}

Recorder::~Recorder() = default;
Recorder::Recorder(Recorder&&) noexcept = default;
Recorder& Recorder::operator=(Recorder&&) noexcept = default;

void Recorder::Capture(const Batch& batch, double time, std::int64_t step) {
  if (!state_ || state_->writer.closed()) throw std::logic_error("Recorder: Capture after Close");
  State& s = *state_;
  if (batch.body_count() != s.bodies || batch.constraint_count() != s.constraints ||
      batch.JointCoordinatesPerWorld() != s.coordinates ||
      batch.world_count() <= *std::max_element(s.worlds.begin(), s.worlds.end())) {
    throw std::invalid_argument(
        "Recorder::Capture: the batch is not the recorded scene's (bodies, constraints, joint "
        "coordinates or world count differ)");
  }
  // Only the recorded worlds are read: a frame of 3 worlds costs the same
  // whether the batch holds 16 worlds or 16384.
  const std::size_t B = s.bodies, J = s.coordinates;
  s.state.resize(B * kStateFloatsPerBody);
  s.coordinate_rows.resize(s.worlds.size() * J);
  const std::span<const std::uint8_t> health = batch.WorldHealth();
  s.positions.clear();
  s.rotations.clear();
  s.health.clear();
  for (std::size_t i = 0; i < s.worlds.size(); ++i) {
    const std::size_t world = s.worlds[i];
    batch.GetWorldState(world, s.state);
    for (std::size_t b = 0; b < B; ++b) {
      const float* body = s.state.data() + b * kStateFloatsPerBody;
      const float* position = body + StateFieldOffset(StateField::kPosition);
      const float* rotation = body + StateFieldOffset(StateField::kRotation);
      s.positions.insert(s.positions.end(), position, position + 3);
      s.rotations.insert(s.rotations.end(), rotation, rotation + 4);
    }
    batch.GetWorldJointCoordinates(world, std::span(s.coordinate_rows).subspan(i * J, J));
    s.health.push_back(health.empty() ? 0 : health[world]);
  }
  npz::StreamingNpzWriter& w = s.writer;
  w.Append(s.time_array, std::as_bytes(std::span(&time, 1)));
  w.Append(s.step_array, std::as_bytes(std::span(&step, 1)));
  w.Append(s.position_array, Bytes(s.positions));
  w.Append(s.rotation_array, Bytes(s.rotations));
  w.Append(s.coordinate_array, Bytes(s.coordinate_rows));
  w.Append(s.health_array, Bytes(s.health));
  ++s.frames;
}

void Recorder::Close() {
  if (!state_ || state_->writer.closed()) throw std::logic_error("Recorder: Close called twice");
  state_->writer.Close();
}

void Recorder::Discard() {
  if (state_ && !state_->writer.closed()) state_->writer.Discard();
}

bool Recorder::closed() const { return !state_ || state_->writer.closed(); }
std::size_t Recorder::frame_count() const { return state_ ? state_->frames : 0; }
const std::string& Recorder::path() const {
  if (!state_) throw std::logic_error("Recorder: moved from");
  return state_->writer.path();
}

}  // namespace manyworlds
