// The cloth of a table camera's frame (table_finder.h's first step): its colour, the pixels of
// about that colour, and the region they make. Split from the table finder, which fits the
// table's sides to the region's outline.
//
// The cloth's colour is the mode of the frame's colours in CIE L*a*b*, weighted towards the image
// centre; its pixels are those of about its chromaticity (b, g over b + g + r: vignetting and
// mixed lights change the brightness much more than it) and brightness, off strong edges.
#pragma once

#include <cstddef>
#include <opencv2/core.hpp>
#include <vector>

namespace billiard::estimator {

// The cloth's candidate colours (BGR) in a reduced BGR frame, up to `count`, the likeliest first:
// the modes of the centre-weighted L*a*b* histogram, each the mean of its pixels, each another
// colour than those before it. The first is the cloth of a table that fills the frame's middle;
// a table seen from a low camera is a band across the middle (its image's height is about the
// sine of the elevation times its width), and the floor or wall around it can outweigh it
// (table_finder.h tries the next colour where the first's region makes no table).
std::vector<cv::Vec3f> ClothColours(const cv::Mat& small, std::size_t count);

// The CIE L*a*b* of a BGR colour (0..255 a channel).
cv::Vec3f LabOfBgr(const cv::Vec3f& bgr);

// Pixels of about the cloth's chromaticity and brightness, off strong edges [255 where cloth].
cv::Mat ClothLike(const cv::Mat& small, const cv::Vec3f& cloth);

// The cloth-like region that is largest once weighted by how central it is [255 in it].
cv::Mat LargestCentralRegion(const cv::Mat& cloth_like);

// The region with its holes (balls, chalk, hands on the cloth) filled.
cv::Mat FillHoles(const cv::Mat& region);

}  // namespace billiard::estimator
