// A directory of images: played in the order of their names, one interval apart, other files
// passed over, an image that does not decode one failed frame, an empty directory refused.
#include "tools/camera_node/image_directory_source.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "tools/camera_node/testing/video_files.h"

namespace billiard::camera_node {
namespace {

namespace fs = std::filesystem;

const cv::Size kSize(120, 60);

std::string FreshDirectory(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/image_directory_source_" + name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(ImageDirectorySource, PlaysTheImagesInTheOrderOfTheirNames) {
  const std::string dir = FreshDirectory("ordered");
  // Written out of order, with names whose order is not the frames' when read as numbers
  // would be: byte order plays frame_09 before frame_10.
  for (int k : {10, 2, 9, 0, 1}) {
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%02d.png", k);
    ASSERT_TRUE(cv::imwrite(dir + name, testing::NumberedFrame(k, kSize)));
  }
  std::ofstream(dir + "/README.txt") << "not an image\n";
  ASSERT_TRUE(cv::imwrite(dir + "/frame_11.PNG", testing::NumberedFrame(11, kSize)));
  ImageDirectorySource source(dir, 20.0);
  ASSERT_EQ(source.Open(), "");
  EXPECT_EQ(source.files().size(), 6u);
  EXPECT_FALSE(source.Live());
  EXPECT_DOUBLE_EQ(source.FrameRate(), 20.0);
  std::vector<int> played;
  std::int64_t first_utime = 0;
  for (int i = 0; i < 6; ++i) {
    const ReadResult r = source.Read();
    ASSERT_EQ(r.kind, ReadResult::Kind::kFrame) << r.reason;
    if (i == 0) first_utime = r.frame.utime;
    EXPECT_EQ(r.frame.utime - first_utime, 50'000 * i);
    played.push_back(testing::FrameNumber(r.frame.image));
  }
  EXPECT_EQ(played, (std::vector<int>{0, 1, 2, 9, 10, 11}));
  const ReadResult end = source.Read();
  EXPECT_EQ(end.kind, ReadResult::Kind::kEnd);
  EXPECT_EQ(end.reason, "the images in '" + dir + "' ended after 6 images");
}

TEST(ImageDirectorySource, AnImageThatDoesNotDecodeIsOneFailedFrame) {
  const std::string dir = FreshDirectory("damaged");
  ASSERT_TRUE(cv::imwrite(dir + "/a.png", testing::NumberedFrame(0, kSize)));
  testing::WriteGarbage(dir + "/b.png");
  ASSERT_TRUE(cv::imwrite(dir + "/c.jpg", testing::NumberedFrame(2, kSize)));
  ImageDirectorySource source(dir, 10.0);
  ASSERT_EQ(source.Open(), "");
  const ReadResult a = source.Read(), b = source.Read(), c = source.Read();
  EXPECT_EQ(a.kind, ReadResult::Kind::kFrame);
  EXPECT_EQ(b.kind, ReadResult::Kind::kBadFrame);
  EXPECT_EQ(b.reason, "'" + dir + "/b.png' is not an image that decodes");
  ASSERT_EQ(c.kind, ReadResult::Kind::kFrame);
  EXPECT_EQ(testing::FrameNumber(c.frame.image), 2);
  // The failed image keeps its place in time.
  EXPECT_EQ(c.frame.utime - a.frame.utime, 200'000);
}

TEST(ImageDirectorySource, ADirectoryWithoutImagesIsRefused) {
  const std::string dir = FreshDirectory("empty");
  std::ofstream(dir + "/notes.txt") << "no frames here\n";
  ImageDirectorySource source(dir, 30.0);
  EXPECT_EQ(source.Open(), "the images in '" + dir + "': there are none");
}

TEST(ImageDirectorySource, ASecondPassGoesOnWithTheClock) {
  const std::string dir = FreshDirectory("looped");
  for (int k = 0; k < 3; ++k) {
    ASSERT_TRUE(
        cv::imwrite(dir + "/" + std::to_string(k) + ".png", testing::NumberedFrame(k, kSize)));
  }
  ImageDirectorySource source(dir, 10.0);
  ASSERT_EQ(source.Open(), "");
  std::vector<std::int64_t> utimes;
  for (int pass = 0; pass < 2; ++pass) {
    for (int k = 0; k < 3; ++k) {
      const ReadResult r = source.Read();
      ASSERT_EQ(r.kind, ReadResult::Kind::kFrame);
      EXPECT_EQ(testing::FrameNumber(r.frame.image), k);
      utimes.push_back(r.frame.utime);
    }
    EXPECT_EQ(source.Read().kind, ReadResult::Kind::kEnd);
    ASSERT_TRUE(source.Restart());
  }
  for (std::size_t i = 1; i < utimes.size(); ++i) EXPECT_EQ(utimes[i] - utimes[i - 1], 100'000);
}

TEST(ImageDirectorySource, ImageFilesAreKnownByTheirExtensionInAnyCase) {
  for (const char* image : {"a.png", "b.JPG", "c.jpeg", "d.bmp", "e.tiff", "f.Tif", "g.pgm",
                            "h.ppm", "i.pnm", "j.webp", "dir/k.png"}) {
    EXPECT_TRUE(IsImageFile(image)) << image;
  }
  for (const char* other : {"a.txt", "b.json", "png", "c.png.bak", "d", "e.avi"}) {
    EXPECT_FALSE(IsImageFile(other)) << other;
  }
}

}  // namespace
}  // namespace billiard::camera_node
