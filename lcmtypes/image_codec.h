// Camera frames between OpenCV and the CAMERA_IMAGE message (billiard::image_t, bot_core layout).
//
// Three pixel formats: GRAY (8 bits per pixel), RGB (R G B bytes, the order bot_core and most
// drivers use, whereas OpenCV keeps B G R) and MJPEG (one JPEG image). Raw rows are packed:
// row_stride = width * bytes per pixel; a decoder accepts any row_stride at least that.
//
// Decoding is the estimator's front door, so it trusts nothing: every field is checked against the
// others and against a size limit before a byte is read, and a JPEG's own header must announce the
// message's width and height before it is decompressed (a small JPEG can claim gigapixels). A
// refused frame comes back with a one-line reason; nothing here throws on bad input or crashes.
//
// JPEGs are decoded with libjpeg, strictly: libjpeg only warns about corrupt entropy-coded data
// or a stream that ends early, and hands back an image damaged from there on (grey, or blocks of
// the wrong colour, where the detector finds balls that are not there and misses those that
// are), so every warning refuses the image. What libjpeg cannot notice stays unnoticed: JPEG has
// no checksum, and bytes flipped in the entropy-coded data often still read as valid codes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "lcmtypes/billiard/image_t.hpp"

namespace billiard::messages {

enum class ImageEncoding { kGray, kRgb, kMjpeg };

// Encodes an 8-bit image (8UC1 gray or 8UC3 BGR; either is converted to what the encoding needs:
// colour to GRAY by OpenCV's luma, gray to RGB by repeating it). `jpeg_quality` (1..100) is for
// MJPEG only; the JPEG keeps the image's channel count. Throws std::invalid_argument on an empty
// image or one of another type, or a quality outside 1..100.
image_t EncodeImage(const cv::Mat& image, std::int64_t utime, ImageEncoding encoding,
                    int jpeg_quality = 90);

struct DecodeLimits {
  int max_width = 4096;
  int max_height = 4096;
};

struct DecodedImage {
  bool ok = false;
  std::string error;  // one line, when !ok
  cv::Mat image;      // 8UC1 for GRAY and gray JPEGs, 8UC3 BGR otherwise
};

// Decodes a frame, or says in one line why it cannot.
DecodedImage DecodeImage(const image_t& message, const DecodeLimits& limits = {});

// Decodes one JPEG image (an MJPEG frame's data, a .jpg file's bytes) whose header announces a size
// within `limits`, or says in one line why it cannot: not a JPEG, truncated, corrupt (whatever
// libjpeg warns about), or neither gray nor colour. The frames of DecodeImage take this path.
DecodedImage DecodeJpeg(const std::vector<std::uint8_t>& bytes, const DecodeLimits& limits = {});

}  // namespace billiard::messages
