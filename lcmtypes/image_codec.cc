#include "lcmtypes/image_codec.h"

#include <csetjmp>
#include <cstdio>  // before jpeglib.h, which uses FILE
#include <cstring>
#include <functional>
#include <stdexcept>
#include <vector>

#include <jerror.h>
#include <jpeglib.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace billiard::messages {
namespace {

cv::Mat AsChannels(const cv::Mat& image, int channels) {
  if (image.channels() == channels) return image;
  cv::Mat out;
  cv::cvtColor(image, out, channels == 1 ? cv::COLOR_BGR2GRAY : cv::COLOR_GRAY2BGR);
  return out;
}

void CopyRows(const cv::Mat& image, std::vector<std::uint8_t>* data) {
  const std::size_t row_bytes = image.cols * image.elemSize();
  data->resize(row_bytes * image.rows);
  for (int y = 0; y < image.rows; ++y) {
    std::memcpy(data->data() + y * row_bytes, image.ptr(y), row_bytes);
  }
}

DecodedImage Refuse(std::string reason) { return {false, std::move(reason), {}}; }

std::string Size(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

DecodedImage DecodeRaw(const image_t& m, int channels) {
  const long long row_bytes = static_cast<long long>(m.width) * channels;
  if (m.row_stride < row_bytes) {
    return Refuse("row_stride " + std::to_string(m.row_stride) + " is less than the " +
                  std::to_string(row_bytes) + " bytes of a row");
  }
  const long long expected = static_cast<long long>(m.row_stride) * m.height;
  if (static_cast<long long>(m.data.size()) != expected) {
    return Refuse(std::to_string(m.data.size()) +
                  " bytes of data, expected row_stride x height = " + std::to_string(expected));
  }
  // A read-only view of the message's bytes (cv::Mat wants a non-const pointer), then a copy the
  // caller owns.
  const cv::Mat view(m.height, m.width, CV_8UC(channels), const_cast<std::uint8_t*>(m.data.data()),
                     m.row_stride);
  DecodedImage out{true, "", {}};
  if (channels == 3) {
    cv::cvtColor(view, out.image, cv::COLOR_RGB2BGR);
  } else {
    out.image = view.clone();
  }
  return out;
}

// libjpeg's error handling made strict: an error and a warning alike end the decode, back at
// DecompressJpeg's setjmp, with libjpeg's own message. (libjpeg is C: no C++ exception may pass
// through it.)
struct StrictJpegErrors {
  jpeg_error_mgr manager;  // first, since libjpeg hands back a pointer to it
  std::jmp_buf escape;
  char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void AbandonDecode(j_common_ptr jpeg) {
  auto* errors = reinterpret_cast<StrictJpegErrors*>(jpeg->err);
  (*jpeg->err->format_message)(jpeg, errors->message);
  std::longjmp(errors->escape, 1);
}

// Level -1 is a warning: corrupt data, which libjpeg would decode into a damaged image. Levels 0
// and above are trace messages.
void RefuseWarnings(j_common_ptr jpeg, int msg_level) {
  if (msg_level < 0) AbandonDecode(jpeg);
}

// Whether to decompress a JPEG of the size its header announces: "" to go on, else the reason.
using JpegSizeCheck = std::function<std::string(int width, int height)>;

DecodedImage DecompressJpeg(const std::vector<std::uint8_t>& bytes, const JpegSizeCheck& check) {
  jpeg_decompress_struct jpeg;
  StrictJpegErrors errors;
  jpeg.err = jpeg_std_error(&errors.manager);
  errors.manager.error_exit = AbandonDecode;
  errors.manager.emit_message = RefuseWarnings;
  // Declared before the setjmp, so that the way back from libjpeg leaves it to its destructor.
  DecodedImage out;
  if (setjmp(errors.escape) != 0) {
    jpeg_destroy_decompress(&jpeg);
    const bool truncated = errors.manager.msg_code == JWRN_JPEG_EOF;
    return Refuse((truncated ? "JPEG is truncated: " : "JPEG refused by libjpeg: ") +
                  std::string(errors.message));
  }
  jpeg_create_decompress(&jpeg);
  jpeg_mem_src(&jpeg, bytes.data(), bytes.size());
  jpeg_read_header(&jpeg, TRUE);
  out.error = check(static_cast<int>(jpeg.image_width), static_cast<int>(jpeg.image_height));
  if (out.error.empty() && jpeg.num_components != 1 && jpeg.num_components != 3) {
    out.error = "JPEG has " + std::to_string(jpeg.num_components) +
                " components; only gray (1) and colour (3) are decoded";
  }
  if (!out.error.empty()) {
    jpeg_destroy_decompress(&jpeg);
    return out;
  }
  const bool gray = jpeg.num_components == 1;
  jpeg.out_color_space = gray ? JCS_GRAYSCALE : JCS_EXT_BGR;
  jpeg_start_decompress(&jpeg);
  out.image.create(static_cast<int>(jpeg.output_height), static_cast<int>(jpeg.output_width),
                   gray ? CV_8UC1 : CV_8UC3);
  while (jpeg.output_scanline < jpeg.output_height) {
    JSAMPROW row = out.image.ptr(static_cast<int>(jpeg.output_scanline));
    jpeg_read_scanlines(&jpeg, &row, 1);
  }
  jpeg_finish_decompress(&jpeg);  // on to the end marker: a stream cut after the last row warns
  jpeg_destroy_decompress(&jpeg);
  out.ok = true;
  return out;
}

// An MJPEG frame: its JPEG must be of the message's size.
DecodedImage DecodeJpegFrame(const image_t& m) {
  return DecompressJpeg(m.data, [&m](int width, int height) {
    if (width == m.width && height == m.height) return std::string();
    return "JPEG is " + Size(width, height) + ", message says " + Size(m.width, m.height);
  });
}

}  // namespace

image_t EncodeImage(const cv::Mat& image, std::int64_t utime, ImageEncoding encoding,
                    int jpeg_quality) {
  if (image.empty() || (image.type() != CV_8UC1 && image.type() != CV_8UC3)) {
    throw std::invalid_argument("EncodeImage: need a non-empty 8UC1 or 8UC3 image");
  }
  if (jpeg_quality < 1 || jpeg_quality > 100) {
    throw std::invalid_argument("EncodeImage: JPEG quality must be within 1..100");
  }
  image_t m;
  m.utime = utime;
  m.width = image.cols;
  m.height = image.rows;
  switch (encoding) {
    case ImageEncoding::kGray:
      m.pixelformat = image_t::PIXEL_FORMAT_GRAY;
      m.row_stride = image.cols;
      CopyRows(AsChannels(image, 1), &m.data);
      break;
    case ImageEncoding::kRgb: {
      cv::Mat rgb;
      cv::cvtColor(AsChannels(image, 3), rgb, cv::COLOR_BGR2RGB);
      m.pixelformat = image_t::PIXEL_FORMAT_RGB;
      m.row_stride = image.cols * 3;
      CopyRows(rgb, &m.data);
      break;
    }
    case ImageEncoding::kMjpeg:
      m.pixelformat = image_t::PIXEL_FORMAT_MJPEG;
      m.row_stride = 0;
      cv::imencode(".jpg", image, m.data, {cv::IMWRITE_JPEG_QUALITY, jpeg_quality});
      break;
  }
  m.size = static_cast<std::int32_t>(m.data.size());
  return m;
}

DecodedImage DecodeImage(const image_t& m, const DecodeLimits& limits) {
  if (m.width <= 0 || m.height <= 0) {
    return Refuse("image size " + Size(m.width, m.height) + " is not positive");
  }
  if (m.width > limits.max_width || m.height > limits.max_height) {
    return Refuse("image size " + Size(m.width, m.height) + " exceeds the limit " +
                  Size(limits.max_width, limits.max_height));
  }
  if (m.size < 0 || static_cast<std::size_t>(m.size) != m.data.size()) {
    return Refuse("size field " + std::to_string(m.size) + " disagrees with the " +
                  std::to_string(m.data.size()) + " bytes of data");
  }
  if (m.data.empty()) return Refuse("no image data");
  switch (m.pixelformat) {
    case image_t::PIXEL_FORMAT_GRAY:
      return DecodeRaw(m, 1);
    case image_t::PIXEL_FORMAT_RGB:
      return DecodeRaw(m, 3);
    case image_t::PIXEL_FORMAT_MJPEG:
      return DecodeJpegFrame(m);
    default:
      return Refuse("unknown pixelformat " + std::to_string(m.pixelformat) +
                    " (GRAY, RGB and MJPEG are decoded)");
  }
}

DecodedImage DecodeJpeg(const std::vector<std::uint8_t>& bytes, const DecodeLimits& limits) {
  return DecompressJpeg(bytes, [&limits](int width, int height) {
    if (width <= limits.max_width && height <= limits.max_height) return std::string();
    return "JPEG is " + Size(width, height) + ", beyond the limit " +
           Size(limits.max_width, limits.max_height);
  });
}

}  // namespace billiard::messages
