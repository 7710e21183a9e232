// Frames from a directory of image files, played in name order (byte order of the file names:
// number them with leading zeros, frame_0009.png before frame_0010.png).
//
// The files are those whose extension OpenCV's imread reads (.png, .jpg, .jpeg, .bmp, .tif,
// .tiff, .pgm, .ppm, .pnm, .webp, any case); others in the directory (a README, a camera model)
// are passed over. The list is taken when the source opens. An image that does not decode is
// one failed frame, said with its name, and the next one plays; a directory without an image
// fails. The n-th image (from 0) is stamped n / rate after the opening: image files carry no
// capture time that every writer fills in.
//
// Module: billiard::camera_node.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tools/camera_node/frame_source.h"

namespace billiard::camera_node {

// Whether `path`'s extension is one of the images' above.
bool IsImageFile(const std::string& path);

class ImageDirectorySource : public FrameSource {
 public:
  // `rate` > 0 [Hz].
  ImageDirectorySource(std::string directory, double rate);

  std::string Describe() const override { return "the images in '" + directory_ + "'"; }
  std::string Open() override;
  ReadResult Read() override;
  // The first image again, stamped one interval after the last.
  bool Restart() override;
  double FrameRate() const override { return rate_; }
  bool Live() const override { return false; }

  // The image files in the order they play (after Open).
  const std::vector<std::string>& files() const { return files_; }

 private:
  const std::string directory_;
  const double rate_;
  std::vector<std::string> files_;
  std::size_t next_ = 0;     // the file the next read plays
  long played_ = 0;          // reads so far, over every pass: the capture times' index
  std::int64_t origin_ = 0;  // the capture time of the first image [us]
};

}  // namespace billiard::camera_node
