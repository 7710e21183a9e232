// labels.json read: a malformed one refused with a one-line reason naming the file and the entry,
// a well-formed one read with its notes skipped and its pocketed and ignored balls together.
#include "bench/labelled_set.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace billiard::bench {
namespace {

TEST(LabelledSet, AMalformedLabelsFileIsRefusedNamingTheEntry) {
  const std::string dir = std::filesystem::temp_directory_path() / "billiard_labels_test";
  std::filesystem::create_directories(dir);
  const auto refusal = [&](const std::string& json) {
    std::ofstream(dir + "/labels.json") << json;
    try {
      LoadLabelledSet(dir);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refusal("{").find("not JSON"), std::string::npos);
  EXPECT_NE(refusal("{\"a.png\": {\"balls\": [[1]], \"ball_radius_px\": 5}}").find("'a.png'"),
            std::string::npos);
  EXPECT_NE(refusal("{\"a.png\": {\"balls\": []}}").find("ball_radius_px"), std::string::npos);
  EXPECT_NE(refusal("{\"a.png\": {\"balls\": [], \"ball_radius_px\": 5, \"view\": \"side\"}}")
                .find("view"),
            std::string::npos);
  EXPECT_NE(refusal("{\"_note\": 1}").find("no frame"), std::string::npos);
  std::ofstream(dir + "/labels.json")
      << "{\"_note\": \"x\", \"b.png\": {\"balls\": [[1, 2]], \"in_pocket\": [[3, 4]], "
         "\"ignore\": [[5, 6]], \"ball_radius_px\": 7.5, \"view\": \"oblique\"}}";
  const auto frames = LoadLabelledSet(dir);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].file, "b.png");
  EXPECT_EQ(frames[0].ignored.size(), 2u);
  EXPECT_EQ(frames[0].view, "oblique");
  std::filesystem::remove_all(dir);
  EXPECT_THROW(LoadLabelledSet(dir), std::invalid_argument);
}

}  // namespace
}  // namespace billiard::bench
