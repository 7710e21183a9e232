#include "plot/canvas.h"

#include <cairo-svg.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace billiard::plot {

std::string FormatOf(const std::string& path) {
  if (path.size() < 4) return "";
  std::string ext = path.substr(path.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".png" || ext == ".svg" ? ext.substr(1) : "";
}

Canvas::Canvas(const std::string& path, int width, int height)
    : path_(path), format_(FormatOf(path)) {
  if (format_.empty()) {
    throw std::invalid_argument("'" + path + "': a picture is a .png or an .svg file");
  }
  surface_ = format_ == "png" ? cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height)
                              : cairo_svg_surface_create(path.c_str(), width, height);
  if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS) {
    const std::string why = cairo_status_to_string(cairo_surface_status(surface_));
    cairo_surface_destroy(surface_);
    throw std::runtime_error("cannot write '" + path + "': " + why);
  }
  cr_ = cairo_create(surface_);
  cairo_set_source_rgb(cr_, 1, 1, 1);
  cairo_paint(cr_);
}

Canvas::~Canvas() {
  if (cr_) cairo_destroy(cr_);
  if (surface_) cairo_surface_destroy(surface_);
}

void Canvas::Finish() {
  cairo_status_t status = cairo_status(cr_);
  if (status == CAIRO_STATUS_SUCCESS && format_ == "png") {
    status = cairo_surface_write_to_png(surface_, path_.c_str());
  }
  cairo_surface_finish(surface_);
  if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface_);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error("cannot write '" + path_ + "': " + cairo_status_to_string(status));
  }
}

void Text(cairo_t* cr, double x, double y, const std::string& text, double size, double align) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  cairo_move_to(cr, x - align * extents.x_advance, y);
  cairo_show_text(cr, text.c_str());
  // show_text leaves a current point: a shape drawn next would begin with a line from it.
  cairo_new_path(cr);
}

}  // namespace billiard::plot
