// The scene ids of manyworlds/scenes.h as the program and Python show them:
// every id has a description, and an unknown id is refused by every entry
// point with one message that lists every valid id, grouped.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

#include "manyworlds/scenes.h"

namespace manyworlds {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

TEST(SceneIds, EveryIdHasAShortDescription) {
  for (const std::string& id : AllSceneIds()) {
    const std::string description = SceneDescription(id);
    EXPECT_FALSE(description.empty()) << id;
    // One line in `manyworlds scenes` next to the id and the counts.
    EXPECT_LE(description.size(), 90u) << id << ": " << description;
    EXPECT_EQ(description.find('\n'), std::string::npos) << id;
  }
}

// The message of the std::invalid_argument that `call` throws; "" if none.
std::string RefusalOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SceneIds, UnknownIdListsEveryValidIdGrouped) {
  const std::string make = RefusalOf([] { (void)MakeScene("nosuch"); });
  EXPECT_THAT(make, StartsWith("unknown scene 'nosuch'; valid ids: reference scenes cartpole, "));
  EXPECT_THAT(make, HasSubstr("; stress scenes chain16-r1000, chain64, spring-0.1"));
  EXPECT_THAT(make, HasSubstr("; contact scenes box-drop, sphere-roll, pile, box-stack, box-pile"));
  for (const std::string& id : AllSceneIds()) EXPECT_THAT(make, HasSubstr(id));
  // The other entry points that take any id say the same.
  EXPECT_EQ(RefusalOf([] { (void)SceneStepSettings("nosuch"); }), make);
  EXPECT_EQ(RefusalOf([] { (void)SceneDescription("nosuch"); }), make);
  EXPECT_EQ(RefusalOf([] { (void)SceneActions("nosuch"); }), make);
}

}  // namespace
}  // namespace manyworlds
