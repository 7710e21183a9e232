// image_t on CAMERA_IMAGE: the message through message_checks, then its pixels through
// DecodeImage (GRAY, RGB, and JPEG through libjpeg, its warnings refused).
#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "fuzz/support.h"
#include "lcmtypes/image_codec.h"
#include "lcmtypes/testing/damaged_jpeg.h"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace billiard::fuzz {
namespace {

// Small limits keep an execution fast (a few-byte JPEG may announce the whole limit) and reach
// the same code as the estimator's.
const messages::DecodeLimits kLimits{1024, 1024};

cv::Mat Pattern(int width, int height) {
  cv::Mat image(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      image.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<uchar>(8 * x), static_cast<uchar>(10 * y),
                                            static_cast<uchar>(37 * (x ^ y)));
    }
  }
  cv::circle(image, {width / 2, height / 2}, height / 3, cv::Scalar(20, 200, 240), cv::FILLED);
  return image;
}

cv::Mat Gray(const cv::Mat& image) {
  cv::Mat gray;
  cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
  return gray;
}

std::string Describe(const image_t& m) {
  return std::to_string(m.width) + "x" + std::to_string(m.height) + " pixelformat " +
         std::to_string(m.pixelformat);
}

// What a decoded frame must be: the announced size, the channels of its format, and the same
// pixels again after a round trip through the encoder the simulator uses.
void RequireDecodedFrame(const image_t& m, const messages::DecodedImage& d) {
  if (!d.error.empty() || d.image.empty() || d.image.cols != m.width || d.image.rows != m.height) {
    Fail("DecodeImage accepted a " + Describe(m) + " frame as " + std::to_string(d.image.cols) +
         "x" + std::to_string(d.image.rows) + " (error '" + d.error + "')");
  }
  const bool gray = d.image.type() == CV_8UC1;
  if ((!gray && d.image.type() != CV_8UC3) ||
      (m.pixelformat == image_t::PIXEL_FORMAT_GRAY && !gray) ||
      (m.pixelformat == image_t::PIXEL_FORMAT_RGB && gray)) {
    Fail("DecodeImage gave OpenCV type " + std::to_string(d.image.type()) + " for a " +
         Describe(m) + " frame");
  }
  const messages::ImageEncoding encoding =
      m.pixelformat == image_t::PIXEL_FORMAT_GRAY  ? messages::ImageEncoding::kGray
      : m.pixelformat == image_t::PIXEL_FORMAT_RGB ? messages::ImageEncoding::kRgb
                                                   : messages::ImageEncoding::kMjpeg;
  const messages::DecodedImage again =
      messages::DecodeImage(messages::EncodeImage(d.image, m.utime, encoding), kLimits);
  if (!again.ok || again.image.size() != d.image.size() || again.image.type() != d.image.type()) {
    Fail("a decoded " + Describe(m) +
         " frame, encoded again, does not decode to its size: " + again.error);
  }
  if (encoding != messages::ImageEncoding::kMjpeg &&
      cv::norm(again.image, d.image, cv::NORM_INF) != 0) {
    Fail("a decoded " + Describe(m) + " frame changes in a raw round trip");
  }
}

}  // namespace

std::vector<Bytes> Seeds() {
  const cv::Mat colour = Pattern(32, 24);
  const cv::Mat gray = Gray(colour);
  // Drivers pad rows: 5 bytes after each.
  image_t padded = messages::EncodeImage(gray, 3, messages::ImageEncoding::kGray);
  padded.row_stride = gray.cols + 5;
  padded.data.clear();
  for (int y = 0; y < gray.rows; ++y) {
    padded.data.insert(padded.data.end(), gray.ptr(y), gray.ptr(y) + gray.cols);
    padded.data.insert(padded.data.end(), 5, 0);
  }
  padded.size = static_cast<std::int32_t>(padded.data.size());
  // Damaged JPEGs, refused, from which mutations reach libjpeg's corrupt-data paths.
  const image_t jpeg = messages::EncodeImage(colour, 4, messages::ImageEncoding::kMjpeg, 75);
  using messages::testing::WithData;
  return {Encode(messages::EncodeImage(colour, 1, messages::ImageEncoding::kGray)),
          Encode(messages::EncodeImage(colour, 2, messages::ImageEncoding::kRgb)),
          Encode(padded),
          Encode(jpeg),
          Encode(messages::EncodeImage(gray, 5, messages::ImageEncoding::kMjpeg, 90)),
          Encode(WithData(jpeg, messages::testing::Truncated(jpeg.data, jpeg.data.size() * 2 / 3))),
          Encode(WithData(jpeg, messages::testing::WithStrayMarker(jpeg.data, 0.5)))};
}

}  // namespace billiard::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace billiard;
  image_t m;
  if (!fuzz::DecodeAndCheck(data, size, m)) return 0;
  // DecodeImage is the estimator's front door whatever Check said of the header, so it gets
  // every message that decodes.
  const messages::DecodedImage d = messages::DecodeImage(m, fuzz::kLimits);
  if (d.ok) {
    fuzz::RequireDecodedFrame(m, d);
  } else {
    fuzz::RequireOneLine(d.error, "DecodeImage");
  }
  return 0;
}

// Half the mutations are libFuzzer's, on the whole payload (the wire layout and the header
// fields); the other half mutate the pixel bytes alone and fix the size field, because a byte
// inserted into or erased from a payload almost never leaves a message that decodes, and the
// JPEG decoder would then rarely be reached.
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t max_size, unsigned int seed) {
  billiard::image_t m;
  if (seed % 2 == 0 || !billiard::messages::Decode(data, size, m).empty() || m.data.empty()) {
    return LLVMFuzzerMutate(data, size, max_size);
  }
  const std::size_t header = size - m.data.size();
  if (max_size <= header) return LLVMFuzzerMutate(data, size, max_size);
  const std::size_t pixels = m.data.size();
  m.data.resize(max_size - header);
  m.data.resize(LLVMFuzzerMutate(m.data.data(), pixels, m.data.size()));
  m.size = static_cast<std::int32_t>(m.data.size());
  const billiard::fuzz::Bytes bytes = billiard::fuzz::Encode(m);
  std::copy(bytes.begin(), bytes.end(), data);
  return bytes.size();
}
