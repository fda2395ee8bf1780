// Recorder (include/manyworlds/recording.h): the file is the NPZ numpy.load
// reads (checked by a small ZIP + NPY reader here, and by Debian's numpy when
// /usr/bin/python3 has it), its frames equal GetState / GetJointCoordinates
// bit for bit, the bodies' collision shapes are the scene's, and no file is
// left after an error or without Close.

#include <sys/resource.h>

#include <csignal>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "batch/npz_writer.h"
#include "manyworlds/batch.h"
#include "manyworlds/recording.h"
#include "manyworlds/scenes.h"
#include "tools/subprocess.h"

namespace manyworlds {
namespace {

namespace fs = std::filesystem;

// One NPY member of an NPZ: its header dict and data bytes.
struct Member {
  std::string header;
  std::string data;
  std::uint32_t crc;
  std::string raw;  // the whole member, for the CRC check
};

std::uint64_t Le(const std::string& bytes, std::size_t at, int size) {
  std::uint64_t v = 0;
  for (int i = size - 1; i >= 0; --i) v = (v << 8) | std::uint8_t(bytes.at(at + std::size_t(i)));
  return v;
}

// A reader of exactly what numpy.savez writes (stored members, no comment),
// following the central directory as zipfile does, ZIP64 included.
std::map<std::string, Member> ReadNpz(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t end = file.size() - 22;
  EXPECT_EQ(Le(file, end, 4), 0x06054b50u);
  std::uint64_t entries = Le(file, end + 10, 2), directory = Le(file, end + 16, 4);
  if (directory == 0xFFFFFFFFu) {  // ZIP64: the locator precedes the end record
    EXPECT_EQ(Le(file, end - 20, 4), 0x07064b50u);
    const std::size_t record = Le(file, end - 12, 8);
    EXPECT_EQ(Le(file, record, 4), 0x06064b50u);
    entries = Le(file, record + 32, 8);
    directory = Le(file, record + 48, 8);
  }
  std::map<std::string, Member> members;
  std::size_t at = directory;
  for (std::uint64_t e = 0; e < entries; ++e) {
    EXPECT_EQ(Le(file, at, 4), 0x02014b50u);
    EXPECT_EQ(Le(file, at + 10, 2), 0u) << "stored, not compressed";
    const std::uint32_t crc = std::uint32_t(Le(file, at + 16, 4));
    std::uint64_t size = Le(file, at + 24, 4), offset = Le(file, at + 42, 4);
    const std::size_t name_length = Le(file, at + 28, 2), extra = Le(file, at + 30, 2);
    const std::string name = file.substr(at + 46, name_length);
    if (size == 0xFFFFFFFFu) {  // ZIP64 extra: sizes, then offset
      EXPECT_EQ(Le(file, at + 46 + name_length, 2), 1u);
      size = Le(file, at + 46 + name_length + 4, 8);
      offset = Le(file, at + 46 + name_length + 20, 8);
    }
    at += 46 + name_length + extra + Le(file, at + 32, 2);
    EXPECT_EQ(Le(file, offset, 4), 0x04034b50u);
    const std::size_t data = offset + 30 + Le(file, offset + 26, 2) + Le(file, offset + 28, 2);
    Member m;
    m.raw = file.substr(data, size);
    m.crc = crc;
    EXPECT_EQ(m.raw.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
    const std::size_t header_length = Le(m.raw, 8, 2);
    EXPECT_EQ((10 + header_length) % 64, 0u) << name;
    m.header = m.raw.substr(10, header_length);
    m.data = m.raw.substr(10 + header_length);
    EXPECT_EQ(name.substr(name.size() - 4), ".npy");
    members[name.substr(0, name.size() - 4)] = m;
  }
  return members;
}

template <class T>
std::vector<T> Values(const Member& m) {
  std::vector<T> v(m.data.size() / sizeof(T));
  std::memcpy(v.data(), m.data.data(), v.size() * sizeof(T));
  return v;
}

class RecordingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("manyworlds_recording_test_" + std::to_string(::getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  std::size_t FilesInFolder() const {
    return std::size_t(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()));
  }
  fs::path folder_;
};

constexpr std::size_t kWorlds = 20;
constexpr int kSteps = 12;

// Records worlds {7, 0, 19} of the ragdoll with its actions and keeps what
// GetState and GetJointCoordinates said at every frame.
struct Expected {
  std::vector<std::vector<float>> states, coordinates;
};
Expected RecordRagdoll(const fs::path& path, bool force_zip64) {
  Batch batch(MakeScene("ragdoll"), kWorlds);
  const SceneActions actions("ragdoll");
  const std::vector<std::size_t> worlds{7, 0, 19};
  Recorder recorder(batch, path.string(), worlds,
                    RecorderOptions{.scene = "ragdoll", .overwrite = false, .force_zip64 = force_zip64});
  Expected expected;
  for (int step = 0; step <= kSteps; ++step) {
    if (step > 0) {
      actions.Apply(batch, std::uint64_t(step - 1), 1);
      batch.Step(StepSettings{});
    }
    recorder.Capture(batch, step / 60.0, step);
    expected.states.emplace_back(batch.world_count() * batch.body_count() * kStateFloatsPerBody);
    batch.GetState(expected.states.back());
    expected.coordinates.emplace_back(batch.world_count() * batch.JointCoordinatesPerWorld());
    batch.GetJointCoordinates(expected.coordinates.back());
  }
  EXPECT_FALSE(fs::exists(path)) << "the file appears only at Close";
  recorder.Close();
  return expected;
}

void CheckRagdollFile(const fs::path& path, const Expected& expected) {
  const Batch batch(MakeScene("ragdoll"), 1);
  const std::size_t B = batch.body_count(), J = batch.JointCoordinatesPerWorld(), T = kSteps + 1;
  const std::vector<std::size_t> worlds{7, 0, 19};
  auto members = ReadNpz(path);
  ASSERT_EQ(members.size(), 24u);
  for (const auto& [name, m] : members) {
    EXPECT_EQ(npz::Crc32(std::as_bytes(std::span(m.raw))), m.crc) << name;
  }
  const std::string position_header = "{'descr': '<f4', 'fortran_order': False, 'shape': (" +
                                      std::to_string(T) + ", 3, " + std::to_string(B) + ", 3), }";
  EXPECT_EQ(members["position"].header.substr(0, position_header.size()), position_header);
  EXPECT_EQ(Values<std::int32_t>(members["format_version"]), std::vector<std::int32_t>{1});
  EXPECT_EQ(members["scene"].header.substr(0, 13), "{'descr': '<U");
  EXPECT_EQ(Values<std::int64_t>(members["world"]), std::vector<std::int64_t>({7, 0, 19}));
  EXPECT_EQ(Values<std::int64_t>(members["step"]).back(), kSteps);
  const auto positions = Values<float>(members["position"]);
  const auto rotations = Values<float>(members["rotation"]);
  const auto coordinates = Values<float>(members["joint_coordinates"]);
  ASSERT_EQ(positions.size(), T * 3 * B * 3);
  ASSERT_EQ(coordinates.size(), T * 3 * J);
  for (std::size_t t = 0; t < T; ++t) {
    for (std::size_t w = 0; w < 3; ++w) {
      for (std::size_t b = 0; b < B; ++b) {
        const float* state =
            expected.states[t].data() + (worlds[w] * B + b) * kStateFloatsPerBody;
        // Bit for bit: memcmp, not ==, so that -0 and NaN payloads count too.
        EXPECT_EQ(std::memcmp(&positions[((t * 3 + w) * B + b) * 3], state, 12), 0);
        EXPECT_EQ(std::memcmp(&rotations[((t * 3 + w) * B + b) * 4], state + 3, 16), 0);
      }
      EXPECT_EQ(std::memcmp(&coordinates[(t * 3 + w) * J],
                            expected.coordinates[t].data() + worlds[w] * J, J * 4),
                0);
    }
  }
}

TEST_F(RecordingTest, FramesEqualTheBatchBitForBit) {
  const fs::path path = folder_ / "ragdoll.npz";
  CheckRagdollFile(path, RecordRagdoll(path, false));
  EXPECT_EQ(FilesInFolder(), 1u) << "no temporary file left";
}

TEST_F(RecordingTest, Zip64RecordsReadTheSame) {
  const fs::path path = folder_ / "ragdoll64.npz";
  CheckRagdollFile(path, RecordRagdoll(path, true));
}

// numpy itself (Debian's /usr/bin/python3): both layouts load, every CRC
// checks out (zipfile.testzip) and the shapes are those of docs/recording.md.
TEST_F(RecordingTest, NumpyLoadsIt) {
  const fs::path python = "/usr/bin/python3";
  if (!fs::exists(python)) GTEST_SKIP() << "no /usr/bin/python3";
  const std::string check =
      "import sys, zipfile, numpy as np\n"
      "for path in sys.argv[1:]:\n"
      "    assert zipfile.ZipFile(path).testzip() is None\n"
      "    d = np.load(path, allow_pickle=False)\n"
      "    T, B, J = len(d['time']), len(d['body_name']), len(d['joint_coordinate_name'])\n"
      "    assert d['position'].shape == (T, 3, B, 3) and d['rotation'].shape == (T, 3, B, 4)\n"
      "    assert d['joint_coordinates'].shape == (T, 3, J) and d['health'].shape == (T, 3)\n"
      "    assert str(d['scene']) == 'ragdoll' and d['body_name'][0] == 'pelvis'\n"
      "    assert d['constraint_anchor'].shape == (len(d['constraint_name']), 2, 3)\n"
      "    assert list(d['world']) == [7, 0, 19] and d['format_version'][0] == 1\n"
      "    assert d['body_shape_type'].dtype == np.uint8 and d['body_shape_type'].shape == (B,)\n"
      "    assert d['body_shape_size'].dtype == np.float32 and d['body_shape_size'].shape == (B, 5)\n"
      "    assert d['body_shape_position'].shape == (B, 3)\n"
      "    assert d['body_shape_rotation'].shape == (B, 4)\n"
      "    assert not d['body_shape_type'].any() and not d['body_shape_size'].any()\n";
  RecordRagdoll(folder_ / "a.npz", false);
  RecordRagdoll(folder_ / "b.npz", true);
  EXPECT_NO_THROW(tools::RunInFolder(python, {"-c", check, "a.npz", "b.npz"}, folder_));
}

// Every shape type: the arrays body_shape_* hold the settings' values bit
// for bit, only the sizes a type uses (the others 0), and a body without a
// shape writes zeros and the identity, whatever its ShapeSettings hold.
TEST_F(RecordingTest, ShapesAreTheScenes) {
  Scene scene;
  BodySettings ground;
  ground.name = "ground";
  ground.motion_type = MotionType::kStatic;
  ground.position = {0.0f, -0.25f, 0.0f};
  ground.shape.type = ShapeType::kPlane;
  ground.shape.position = {0.0f, 0.125f, 0.0f};
  ground.shape.rotation = {0.0f, 0.0f, 0.09983342f, 0.99500417f};  // 0.2 rad about Z
  ground.shape.radius = 7.0f;  // not used by a plane: recorded as 0
  scene.AddBody(ground);
  BodySettings sphere;
  sphere.name = "sphere";
  sphere.position = {0.0f, 1.0f, 0.0f};
  sphere.shape.type = ShapeType::kSphere;
  sphere.shape.radius = 0.3f;
  sphere.shape.half_height = 2.0f;  // not used by a sphere
  scene.AddBody(sphere);
  BodySettings capsule;
  capsule.name = "capsule";
  capsule.position = {2.0f, 1.0f, 0.0f};
  capsule.shape.type = ShapeType::kCapsule;
  capsule.shape.radius = 0.15f;
  capsule.shape.half_height = 0.35f;
  capsule.shape.half_extents = {9.0f, 9.0f, 9.0f};  // not used by a capsule
  capsule.shape.position = {0.1f, -0.2f, 0.3f};
  capsule.shape.rotation = {0.0f, 0.0f, -0.70710677f, 0.70710677f};  // Y onto X
  scene.AddBody(capsule);
  BodySettings box;
  box.name = "box";
  box.position = {-2.0f, 1.0f, 0.0f};
  box.shape.type = ShapeType::kBox;
  box.shape.half_extents = {0.4f, 0.25f, 0.3f};
  box.shape.radius = 5.0f;  // not used by a box
  box.shape.rotation = {0.0f, 0.38268343f, 0.0f, 0.92387953f};  // 45 degrees about Y
  scene.AddBody(box);
  BodySettings none;
  none.name = "none";
  none.position = {0.0f, 3.0f, 0.0f};
  none.shape.radius = 0.7f;  // type kNone: none of this is recorded
  none.shape.position = {1.0f, 2.0f, 3.0f};
  none.shape.rotation = {0.0f, 1.0f, 0.0f, 0.0f};
  scene.AddBody(none);

  Batch batch(scene, 2);
  const fs::path path = folder_ / "shapes.npz";
  Recorder recorder(batch, path.string(), std::vector<std::size_t>{1});
  recorder.Capture(batch, 0.0, 0);
  recorder.Close();
  auto members = ReadNpz(path);
  const auto header = [&](const std::string& name, const std::string& descr,
                          const std::string& shape) {
    const std::string expected =
        "{'descr': '" + descr + "', 'fortran_order': False, 'shape': " + shape + ", }";
    EXPECT_EQ(members[name].header.substr(0, expected.size()), expected) << name;
  };
  header("body_shape_type", "|u1", "(5,)");
  header("body_shape_size", "<f4", "(5, 5)");
  header("body_shape_position", "<f4", "(5, 3)");
  header("body_shape_rotation", "<f4", "(5, 4)");

  EXPECT_EQ(Values<std::uint8_t>(members["body_shape_type"]),
            std::vector<std::uint8_t>({4, 1, 2, 3, 0}));
  // Bits, not values: the recorded floats are the settings' own.
  const auto bits = [](const std::vector<float>& values) {
    std::vector<std::uint32_t> b(values.size());
    std::memcpy(b.data(), values.data(), values.size() * 4);
    return b;
  };
  const auto size = bits(Values<float>(members["body_shape_size"]));
  EXPECT_EQ(size, bits({0, 0, 0, 0, 0,                       // plane
                        0.3f, 0, 0, 0, 0,                    // sphere
                        0.15f, 0.35f, 0, 0, 0,               // capsule
                        0, 0, 0.4f, 0.25f, 0.3f,             // box
                        0, 0, 0, 0, 0}));                    // none
  const auto position = bits(Values<float>(members["body_shape_position"]));
  EXPECT_EQ(position, bits({0.0f, 0.125f, 0.0f, 0, 0, 0, 0.1f, -0.2f, 0.3f, 0, 0, 0, 0, 0, 0}));
  const auto rotation = bits(Values<float>(members["body_shape_rotation"]));
  EXPECT_EQ(rotation, bits({0.0f, 0.0f, 0.09983342f, 0.99500417f,    // plane
                            0, 0, 0, 1,                              // sphere
                            0.0f, 0.0f, -0.70710677f, 0.70710677f,   // capsule
                            0.0f, 0.38268343f, 0.0f, 0.92387953f,    // box
                            0, 0, 0, 1}));                           // none
}

// The contact scenes record the shapes they collide with: box-stack is a
// ground plane under five boxes.
TEST_F(RecordingTest, ContactScenesRecordTheirShapes) {
  const Scene scene = MakeScene("box-stack");
  Batch batch(scene, 1);
  const fs::path path = folder_ / "box-stack.npz";
  Recorder recorder(batch, path.string(), std::vector<std::size_t>{0});
  recorder.Capture(batch, 0.0, 0);
  recorder.Close();
  auto members = ReadNpz(path);
  const auto types = Values<std::uint8_t>(members["body_shape_type"]);
  const auto sizes = Values<float>(members["body_shape_size"]);
  ASSERT_EQ(types.size(), scene.bodies().size());
  ASSERT_EQ(sizes.size(), 5 * scene.bodies().size());
  EXPECT_EQ(types, std::vector<std::uint8_t>({4, 3, 3, 3, 3, 3}));
  for (std::size_t b = 0; b < types.size(); ++b) {
    const ShapeSettings& shape = scene.bodies()[b].shape;
    EXPECT_EQ(types[b], static_cast<std::uint8_t>(shape.type)) << b;
    if (shape.type != ShapeType::kBox) continue;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(sizes[5 * b + 2 + std::size_t(k)], shape.half_extents[k]);
  }
}

TEST_F(RecordingTest, NoFileWithoutClose) {
  const fs::path path = folder_ / "never.npz";
  {
    Batch batch(MakeScene("cartpole"), 4);
    Recorder recorder(batch, path.string(), std::vector<std::size_t>{1});
    recorder.Capture(batch, 0.0, 0);
    EXPECT_EQ(FilesInFolder(), 1u);  // the temporary ZIP
  }
  EXPECT_EQ(FilesInFolder(), 0u);
}

TEST_F(RecordingTest, ADiskErrorRemovesThePartialFile) {
  const fs::path path = folder_ / "full.npz";
  Batch batch(MakeScene("chain64"), 64);
  const std::vector<std::size_t> worlds{0, 1, 2, 3, 4, 5, 6, 7};
  // A file size limit stands in for a full disk: writes past it fail EFBIG.
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = old;
  small.rlim_cur = 256 * 1024;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  bool threw = false;
  try {
    Recorder recorder(batch, path.string(), worlds);
    for (int step = 0; step < 200; ++step) recorder.Capture(batch, 0.0, step);
    recorder.Close();
  } catch (const std::runtime_error& e) {
    threw = true;
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_TRUE(threw);
  EXPECT_EQ(FilesInFolder(), 0u);
}

TEST_F(RecordingTest, RefusesBadWorldsAndExistingFiles) {
  Batch batch(MakeScene("cartpole"), 4);
  const fs::path path = folder_ / "r.npz";
  const auto record = [&](std::vector<std::size_t> worlds, bool overwrite = false) {
    Recorder recorder(batch, path.string(), worlds, RecorderOptions{.scene = "", .overwrite = overwrite});
    recorder.Capture(batch, 0.0, 0);
    recorder.Close();
  };
  EXPECT_THROW(record({}), std::invalid_argument);
  EXPECT_THROW(record({4}), std::invalid_argument);
  EXPECT_THROW(record({1, 2, 1}), std::invalid_argument);
  EXPECT_EQ(FilesInFolder(), 0u);
  record({0});
  EXPECT_THROW(record({0}), std::runtime_error);
  EXPECT_NO_THROW(record({1}, true));
  EXPECT_THROW(Recorder(batch, (folder_ / "missing" / "r.npz").string(),
                        std::vector<std::size_t>{0}),
               std::runtime_error);
  EXPECT_EQ(FilesInFolder(), 1u);
}

}  // namespace
}  // namespace manyworlds
