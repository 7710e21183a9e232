// JPEGs damaged the ways a camera link or a disk damages them, for the tests and the fuzz seeds of
// the strict JPEG decoder (lcmtypes/image_codec.h). Each damage is one that libjpeg notices
// wherever it falls and, left to itself, only warns about while it hands back a damaged image.
//
// Not every damage can be noticed: JPEG carries no checksum, and bytes flipped at random in the
// entropy-coded data mostly still read as valid codes (on the real photograph's JPEG libjpeg
// notices about a quarter of single flipped bytes and half of runs of 16 random bytes).
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "lcmtypes/billiard/image_t.hpp"

namespace billiard::messages::testing {

using JpegBytes = std::vector<std::uint8_t>;

// Where the entropy-coded data of a JPEG's first scan starts: just after its SOS header, found by
// walking the marker segments. Throws std::invalid_argument when there is no scan.
inline std::size_t ScanDataStart(const JpegBytes& jpeg) {
  constexpr std::uint8_t kStartOfScan = 0xDA;
  std::size_t at = 2;  // after SOI
  while (at + 4 <= jpeg.size() && jpeg[at] == 0xFF) {
    const std::size_t length = (jpeg[at + 2] << 8) | jpeg[at + 3];
    if (jpeg[at + 1] == kStartOfScan) return at + 2 + length;
    at += 2 + length;
  }
  throw std::invalid_argument("ScanDataStart: no SOS segment in the JPEG");
}

// The offset `fraction` (0 to below 1) of the way through the scan data, which ends at the EOI
// marker.
inline std::size_t IntoScanData(const JpegBytes& jpeg, double fraction) {
  const std::size_t start = ScanDataStart(jpeg), end = jpeg.size() - 2;
  return start + static_cast<std::size_t>(fraction * static_cast<double>(end - start));
}

// `jpeg` with two bytes of its scan data, `fraction` of the way through, turned into a restart
// marker (FF D0) where the stream has none, as bit errors on a link leave one: libjpeg says
// "Corrupt JPEG data: premature end of data segment" and fills the rest of the image.
inline JpegBytes WithStrayMarker(JpegBytes jpeg, double fraction) {
  const std::size_t at = IntoScanData(jpeg, fraction);
  jpeg[at] = 0xFF;
  jpeg[at + 1] = 0xD0;
  return jpeg;
}

// `jpeg` cut `fraction` of the way through its scan data and closed with the EOI marker, as a
// writer that lost data but ended the file leaves it: libjpeg says "Corrupt JPEG data: premature
// end of data segment" and fills the rest of the image.
inline JpegBytes CutAndClosed(JpegBytes jpeg, double fraction) {
  jpeg.resize(IntoScanData(jpeg, fraction));
  if (jpeg.back() == 0xFF) jpeg.pop_back();  // half of a stuffed FF 00
  jpeg.push_back(0xFF);
  jpeg.push_back(0xD9);
  return jpeg;
}

// `jpeg` with 16 bytes of junk between its scan data and the EOI marker, as a frame spliced with
// a piece of another leaves it: libjpeg says "Corrupt JPEG data: N extraneous bytes before marker
// 0xd9" (fewer than 16: it reads a few bytes ahead into the junk as scan data).
inline JpegBytes WithJunkBeforeTheEnd(JpegBytes jpeg) {
  constexpr std::size_t kJunkBytes = 16;
  jpeg.insert(jpeg.end() - 2, kJunkBytes, 0x5A);
  return jpeg;
}

// The first `length` bytes of `jpeg`.
inline JpegBytes Truncated(const JpegBytes& jpeg, std::size_t length) {
  return JpegBytes(jpeg.begin(), jpeg.begin() + static_cast<std::ptrdiff_t>(length));
}

// `frame` with `data` for its bytes, and the size field to match.
inline image_t WithData(image_t frame, JpegBytes data) {
  frame.data = std::move(data);
  frame.size = static_cast<std::int32_t>(frame.data.size());
  return frame;
}

}  // namespace billiard::messages::testing
