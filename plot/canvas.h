// A Cairo drawing surface written to a PNG or an SVG file, chosen by the file's extension.
//
// Module: billiard::plot (plot/). Cairo, Eigen, sim/table/ and sim/physics/.
#pragma once

#include <cairo.h>

#include <string>

namespace billiard::plot {

// ".png" or ".svg" (either case), else "" (no format we write).
std::string FormatOf(const std::string& path);

class Canvas {
 public:
  // A width x height [px] surface for `path`. Throws std::invalid_argument for another extension
  // than .png or .svg, std::runtime_error when the SVG file cannot be made.
  Canvas(const std::string& path, int width, int height);
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  cairo_t* cr() const { return cr_; }

  // Writes the file (an SVG is written as it is drawn and closed here); std::runtime_error if
  // it cannot be.
  void Finish();

 private:
  std::string path_;
  std::string format_;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

// Text with its reference point at (x, y): its left end (align 0), middle (0.5) or right end (1)
// on the baseline.
void Text(cairo_t* cr, double x, double y, const std::string& text, double size,
          double align = 0.0);

}  // namespace billiard::plot
