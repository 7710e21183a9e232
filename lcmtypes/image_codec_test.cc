// The image codec: exact round trips, JPEG within a quality bound, every malformed frame refused.
#include "lcmtypes/image_codec.h"

#include <gtest/gtest.h>

#include <random>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "lcmtypes/testing/damaged_jpeg.h"

namespace billiard::messages {
namespace {

// A colour image with structure a codec can get wrong: a gradient, a disc and per-pixel noise
// (which makes row and channel mix-ups visible).
cv::Mat TestImage(int width = 160, int height = 90) {
  cv::Mat image(height, width, CV_8UC3);
  std::mt19937 rng(7);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      image.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<uchar>(x), static_cast<uchar>(2 * y),
                                            static_cast<uchar>(rng() % 256));
    }
  }
  cv::circle(image, {width / 2, height / 2}, height / 4, cv::Scalar(20, 200, 240), cv::FILLED);
  return image;
}

// A JPEG frame of the test image, smoothed as a camera sees the table.
image_t JpegFrame() {
  cv::Mat smooth;
  cv::GaussianBlur(TestImage(), smooth, {0, 0}, 2.0);
  return EncodeImage(smooth, 0, ImageEncoding::kMjpeg);
}

bool Identical(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

// The refusal's reason must be one line and mention `word`.
void ExpectRefused(const image_t& m, const std::string& word) {
  const DecodedImage d = DecodeImage(m);
  EXPECT_FALSE(d.ok);
  EXPECT_TRUE(d.image.empty());
  EXPECT_NE(d.error.find(word), std::string::npos) << d.error;
  EXPECT_EQ(d.error.find('\n'), std::string::npos) << d.error;
}

TEST(ImageCodec, GrayRoundTripIsExact) {
  cv::Mat gray;
  cv::cvtColor(TestImage(), gray, cv::COLOR_BGR2GRAY);
  const image_t m = EncodeImage(gray, 42, ImageEncoding::kGray);
  EXPECT_EQ(m.pixelformat, image_t::PIXEL_FORMAT_GRAY);
  EXPECT_EQ(m.row_stride, 160);
  EXPECT_EQ(m.size, 160 * 90);
  EXPECT_EQ(m.utime, 42);
  const DecodedImage d = DecodeImage(m);
  ASSERT_TRUE(d.ok) << d.error;
  EXPECT_TRUE(Identical(d.image, gray));
}

TEST(ImageCodec, RgbRoundTripIsExactAndTheBytesAreInRgbOrder) {
  const cv::Mat bgr = TestImage();
  const image_t m = EncodeImage(bgr, 0, ImageEncoding::kRgb);
  EXPECT_EQ(m.pixelformat, image_t::PIXEL_FORMAT_RGB);
  EXPECT_EQ(m.row_stride, 160 * 3);
  ASSERT_EQ(m.size, 160 * 90 * 3);
  const cv::Vec3b p = bgr.at<cv::Vec3b>(10, 7);  // B G R
  const std::size_t at = 10 * m.row_stride + 7 * 3;
  EXPECT_EQ(m.data[at], p[2]);
  EXPECT_EQ(m.data[at + 1], p[1]);
  EXPECT_EQ(m.data[at + 2], p[0]);
  const DecodedImage d = DecodeImage(m);
  ASSERT_TRUE(d.ok) << d.error;
  EXPECT_TRUE(Identical(d.image, bgr));
}

TEST(ImageCodec, RegionsOfLargerImagesAndPaddedRowsRoundTrip) {
  const cv::Mat big = TestImage(200, 120);
  const cv::Mat roi = big(cv::Rect(13, 7, 101, 55));  // not continuous
  DecodedImage d = DecodeImage(EncodeImage(roi, 0, ImageEncoding::kRgb));
  ASSERT_TRUE(d.ok) << d.error;
  EXPECT_TRUE(Identical(d.image, roi));

  // A driver that pads its rows to 4 bytes: the padding is skipped.
  cv::Mat gray;
  cv::cvtColor(roi, gray, cv::COLOR_BGR2GRAY);
  image_t m = EncodeImage(gray, 0, ImageEncoding::kGray);
  m.row_stride = 104;
  m.data.assign(static_cast<std::size_t>(104) * 55, 0xAB);
  for (int y = 0; y < 55; ++y) std::copy(gray.ptr(y), gray.ptr(y) + 101, &m.data[y * 104]);
  m.size = static_cast<int>(m.data.size());
  d = DecodeImage(m);
  ASSERT_TRUE(d.ok) << d.error;
  EXPECT_TRUE(Identical(d.image, gray));
}

TEST(ImageCodec, JpegRoundTripIsWithinItsQuality) {
  // A smooth image, as a camera sees the table; per-pixel noise is what JPEG is not for.
  cv::Mat smooth;
  cv::GaussianBlur(TestImage(320, 180), smooth, {0, 0}, 2.0);
  for (const int quality : {75, 95}) {
    const image_t m = EncodeImage(smooth, 5, ImageEncoding::kMjpeg, quality);
    EXPECT_EQ(m.pixelformat, image_t::PIXEL_FORMAT_MJPEG);
    EXPECT_LT(m.data.size(), smooth.total() * 3 / 2);
    const DecodedImage d = DecodeImage(m);
    ASSERT_TRUE(d.ok) << d.error;
    ASSERT_EQ(d.image.type(), CV_8UC3);
    EXPECT_GT(cv::PSNR(d.image, smooth), quality >= 95 ? 38.0 : 32.0) << "quality " << quality;
  }
  cv::Mat gray;
  cv::cvtColor(smooth, gray, cv::COLOR_BGR2GRAY);
  const DecodedImage d = DecodeImage(EncodeImage(gray, 0, ImageEncoding::kMjpeg, 95));
  ASSERT_TRUE(d.ok) << d.error;
  ASSERT_EQ(d.image.type(), CV_8UC1);
  EXPECT_GT(cv::PSNR(d.image, gray), 38.0);
}

TEST(ImageCodec, EncodeConvertsBetweenGrayAndColourAndRefusesOtherTypes) {
  const cv::Mat bgr = TestImage();
  cv::Mat gray;
  cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
  EXPECT_TRUE(Identical(DecodeImage(EncodeImage(bgr, 0, ImageEncoding::kGray)).image, gray));
  cv::Mat grey_bgr;
  cv::cvtColor(gray, grey_bgr, cv::COLOR_GRAY2BGR);
  EXPECT_TRUE(Identical(DecodeImage(EncodeImage(gray, 0, ImageEncoding::kRgb)).image, grey_bgr));
  EXPECT_THROW(EncodeImage(cv::Mat(), 0, ImageEncoding::kGray), std::invalid_argument);
  EXPECT_THROW(EncodeImage(cv::Mat(4, 4, CV_16UC1), 0, ImageEncoding::kGray),
               std::invalid_argument);
  EXPECT_THROW(EncodeImage(bgr, 0, ImageEncoding::kMjpeg, 0), std::invalid_argument);
}

TEST(ImageCodec, MalformedRawFramesAreRefused) {
  const image_t good = EncodeImage(TestImage(), 0, ImageEncoding::kRgb);
  ASSERT_TRUE(DecodeImage(good).ok);

  image_t m = good;
  m.data.clear();
  m.size = 0;
  ExpectRefused(m, "no image data");

  m = good;
  m.data.pop_back();
  m.size = static_cast<int>(m.data.size());
  ExpectRefused(m, "expected row_stride x height");

  m = good;
  m.size += 1;  // the size field disagrees with the bytes
  ExpectRefused(m, "size field");

  m = good;
  m.row_stride = 160 * 3 - 1;
  ExpectRefused(m, "row_stride");

  m = good;
  m.row_stride = -480;
  ExpectRefused(m, "row_stride");

  for (const auto& [w, h] : {std::pair{0, 90}, {160, 0}, {-160, 90}, {160, -1}}) {
    m = good;
    m.width = w;
    m.height = h;
    ExpectRefused(m, "not positive");
  }
  for (const auto& [w, h] : {std::pair{4097, 90}, {160, 100000}, {2147483647, 2147483647}}) {
    m = good;
    m.width = w;
    m.height = h;
    ExpectRefused(m, "exceeds the limit");
  }
  // A tighter limit of the caller's.
  EXPECT_FALSE(DecodeImage(good, {100, 100}).ok);

  m = good;
  m.pixelformat = 0x56595559;  // 'YUYV': real, but not ours
  ExpectRefused(m, "unknown pixelformat");

  // Raw sizes that would overflow 32-bit arithmetic.
  m = good;
  m.width = 4096;
  m.height = 4096;
  m.row_stride = 2147483647;
  ExpectRefused(m, "expected row_stride x height");
}

TEST(ImageCodec, MalformedJpegsAreRefused) {
  const image_t good = JpegFrame();
  ASSERT_TRUE(DecodeImage(good).ok);

  image_t m = good;
  m.width = 161;
  ExpectRefused(m, "JPEG is 160x90, message says 161x90");
  m = good;
  m.height = 45;
  ExpectRefused(m, "JPEG is 160x90");

  // Garbage of every kind: random bytes, random bytes after a JPEG start, all zeros.
  std::mt19937 rng(11);
  for (int i = 0; i < 200; ++i) {
    m = good;
    m.data.resize(1 + rng() % 5000);
    for (auto& b : m.data) b = static_cast<std::uint8_t>(rng());
    if (i % 2 == 0 && m.data.size() >= 2) {
      m.data[0] = 0xFF;
      m.data[1] = 0xD8;
    }
    m.size = static_cast<int>(m.data.size());
    EXPECT_FALSE(DecodeImage(m).ok);
  }
  m = good;
  std::fill(m.data.begin(), m.data.end(), 0);
  ExpectRefused(m, "Not a JPEG file");

  // Corrupt bytes inside the good JPEG's entropy-coded data and headers: refused where libjpeg
  // notices, else (bytes that still read as valid codes) decoded to the announced size; never a
  // crash.
  for (int i = 0; i < 200; ++i) {
    m = good;
    for (int k = 0; k < 8; ++k) m.data[rng() % m.data.size()] = static_cast<std::uint8_t>(rng());
    const DecodedImage d = DecodeImage(m);
    if (d.ok) {
      EXPECT_EQ(d.image.size(), cv::Size(160, 90));
    } else {
      EXPECT_FALSE(d.error.empty());
    }
  }
}

TEST(ImageCodec, DecodeJpegReadsWhatOpenCvWritesWithinItsLimits) {
  const image_t frame = JpegFrame();
  const DecodedImage d = DecodeJpeg(frame.data);
  ASSERT_TRUE(d.ok) << d.error;
  // The same libjpeg with the same settings: the very pixels OpenCV decodes, in BGR order.
  EXPECT_TRUE(Identical(d.image, cv::imdecode(frame.data, cv::IMREAD_COLOR)));
  cv::Mat gray;
  cv::cvtColor(TestImage(), gray, cv::COLOR_BGR2GRAY);
  const DecodedImage g = DecodeJpeg(EncodeImage(gray, 0, ImageEncoding::kMjpeg).data);
  ASSERT_TRUE(g.ok) << g.error;
  EXPECT_EQ(g.image.type(), CV_8UC1);

  const DecodedImage over = DecodeJpeg(frame.data, {100, 100});
  EXPECT_FALSE(over.ok);
  EXPECT_EQ(over.error, "JPEG is 160x90, beyond the limit 100x100");
}

TEST(ImageCodec, TruncatedJpegsAreRefusedWhereverTheyAreCut) {
  const image_t good = JpegFrame();
  for (std::size_t length = 1; length < good.data.size(); ++length) {
    SCOPED_TRACE("cut after " + std::to_string(length) + " of " + std::to_string(good.data.size()) +
                 " bytes");
    ExpectRefused(testing::WithData(good, testing::Truncated(good.data, length)), "truncated");
  }
}

TEST(ImageCodec, CorruptButCompleteJpegsAreRefused) {
  const image_t good = JpegFrame();
  for (const double at : {0.0, 0.1, 0.3, 0.5, 0.7, 0.9}) {
    SCOPED_TRACE("damaged " + std::to_string(at) + " of the way through the scan data");
    ExpectRefused(testing::WithData(good, testing::WithStrayMarker(good.data, at)),
                  "Corrupt JPEG data: premature end of data segment");
    ExpectRefused(testing::WithData(good, testing::CutAndClosed(good.data, at)),
                  "Corrupt JPEG data: premature end of data segment");
  }
  ExpectRefused(testing::WithData(good, testing::WithJunkBeforeTheEnd(good.data)),
                "extraneous bytes before marker 0xd9");
  const DecodedImage d = DecodeImage(good);
  ASSERT_TRUE(d.ok) << d.error;
  EXPECT_EQ(d.image.size(), cv::Size(160, 90));
}

}  // namespace
}  // namespace billiard::messages
