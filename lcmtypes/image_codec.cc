#include "lcmtypes/image_codec.h"

#include <cstring>
#include <optional>
#include <stdexcept>
#include <vector>

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

struct JpegHeader {
  int width = 0, height = 0, components = 0;
};

// The frame header (SOF) of a JPEG, found by walking the marker segments up to the scan.
std::optional<JpegHeader> ReadJpegHeader(const std::vector<std::uint8_t>& d) {
  if (d.size() < 4 || d[0] != 0xFF || d[1] != 0xD8) return std::nullopt;
  std::size_t i = 2;
  while (i + 4 <= d.size()) {
    if (d[i] != 0xFF) return std::nullopt;
    const std::uint8_t marker = d[i + 1];
    if (marker == 0xFF) {  // fill byte
      ++i;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {  // segments without a length
      i += 2;
      continue;
    }
    const std::size_t length = (d[i + 2] << 8) | d[i + 3];
    if (length < 2 || i + 2 + length > d.size()) return std::nullopt;
    const bool frame_header =
        marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (frame_header) {
      if (length < 8) return std::nullopt;
      const std::uint8_t* s = d.data() + i + 4;
      return JpegHeader{(s[3] << 8) | s[4], (s[1] << 8) | s[2], s[5]};
    }
    if (marker == 0xDA || marker == 0xD9) return std::nullopt;  // scan or end before a frame
    i += 2 + length;
  }
  return std::nullopt;
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

DecodedImage DecodeJpeg(const image_t& m) {
  const std::vector<std::uint8_t>& d = m.data;
  const std::optional<JpegHeader> header = ReadJpegHeader(d);
  if (!header) return Refuse("not a JPEG: no SOI marker or no frame header before the scan");
  if (header->width != m.width || header->height != m.height) {
    return Refuse("JPEG is " + Size(header->width, header->height) + ", message says " +
                  Size(m.width, m.height));
  }
  if (header->components != 1 && header->components != 3) {
    return Refuse("JPEG has " + std::to_string(header->components) +
                  " components; only gray (1) and colour (3) are decoded");
  }
  // libjpeg pads a truncated stream with grey and calls it a warning; the end marker tells.
  if (d[d.size() - 2] != 0xFF || d[d.size() - 1] != 0xD9) {
    return Refuse("JPEG does not end with the EOI marker (truncated)");
  }
  DecodedImage out{true, "", {}};
  try {
    out.image = cv::imdecode(d, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    return Refuse("JPEG does not decode: " + std::string(e.what()).substr(0, 200));
  }
  if (out.image.empty()) return Refuse("JPEG does not decode");
  if (out.image.cols != m.width || out.image.rows != m.height || out.image.depth() != CV_8U) {
    return Refuse("JPEG decodes to " + Size(out.image.cols, out.image.rows) + ", message says " +
                  Size(m.width, m.height));
  }
  return out;
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
      return DecodeJpeg(m);
    default:
      return Refuse("unknown pixelformat " + std::to_string(m.pixelformat) +
                    " (GRAY, RGB and MJPEG are decoded)");
  }
}

}  // namespace billiard::messages
