#pragma once
// Pictures of specimens with cairo (Debian: libcairo2-dev): disks coloured by
// aggregate, mastic dark, voids white; optionally the displacement field.
#include <vrut/specimen/specimen.hpp>

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <random>
#include <string>
#include <vector>

namespace vrut::app::draw {

struct Rgb {
  double r, g, b;
};

// Stone colours, picked by aggregate index so a picture is reproducible.
inline Rgb stone(int aggregate) {
  static const Rgb palette[] = {{0.80, 0.62, 0.42}, {0.66, 0.56, 0.46}, {0.85, 0.74, 0.55}, {0.55, 0.60, 0.62},
                                {0.72, 0.50, 0.36}, {0.90, 0.82, 0.66}, {0.62, 0.66, 0.55}, {0.76, 0.68, 0.60}};
  return palette[static_cast<unsigned>(aggregate) * 2654435761u % 8u];
}

// Blue-to-red colour scale for t in [0, 1].
inline Rgb heat(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return {std::clamp(1.5 - std::abs(4.0 * t - 3.0), 0.0, 1.0), std::clamp(1.5 - std::abs(4.0 * t - 2.0), 0.0, 1.0),
          std::clamp(1.5 - std::abs(4.0 * t - 1.0), 0.0, 1.0)};
}

class Canvas {
 public:
  // A picture of a width x height (mm) section at `scale` pixels per mm, with a margin.
  Canvas(double width_mm, double height_mm, double scale, double margin_mm = 2.0)
      : scale_(scale), margin_(margin_mm), height_mm_(height_mm),
        surface_(cairo_image_surface_create(CAIRO_FORMAT_RGB24, static_cast<int>((width_mm + 2 * margin_mm) * scale),
                                            static_cast<int>((height_mm + 2 * margin_mm) * scale))),
        cr_(cairo_create(surface_)) {
    cairo_set_source_rgb(cr_, 1, 1, 1);
    cairo_paint(cr_);
  }
  ~Canvas() {
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
  }
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  // Section coordinates (mm, y up) to pixels (y down).
  double px(double x) const { return (x + margin_) * scale_; }
  double py(double y) const { return (height_mm_ + margin_ - y) * scale_; }

  void disk(double x, double y, double r, Rgb c) {
    cairo_set_source_rgb(cr_, c.r, c.g, c.b);
    cairo_arc(cr_, px(x), py(y), r * scale_, 0, 2 * M_PI);
    cairo_fill(cr_);
  }
  void polygon(const vrut::Polygon& p, Rgb c, double line_px) {
    cairo_set_source_rgb(cr_, c.r, c.g, c.b);
    cairo_set_line_width(cr_, line_px);
    for (std::size_t k = 0; k < p.vertices.size(); ++k) {
      const auto& v = p.vertices[k];
      k ? cairo_line_to(cr_, px(v.x()), py(v.y())) : cairo_move_to(cr_, px(v.x()), py(v.y()));
    }
    cairo_close_path(cr_);
    cairo_stroke(cr_);
  }
  void fill_polygon(const vrut::Polygon& p, Rgb c) {
    cairo_set_source_rgb(cr_, c.r, c.g, c.b);
    for (std::size_t k = 0; k < p.vertices.size(); ++k) {
      const auto& v = p.vertices[k];
      k ? cairo_line_to(cr_, px(v.x()), py(v.y())) : cairo_move_to(cr_, px(v.x()), py(v.y()));
    }
    cairo_close_path(cr_);
    cairo_fill(cr_);
  }
  void arrow(double x, double y, double dx, double dy, Rgb c, double line_px) {
    cairo_set_source_rgb(cr_, c.r, c.g, c.b);
    cairo_set_line_width(cr_, line_px);
    const double x1 = px(x), y1 = py(y), x2 = px(x + dx), y2 = py(y + dy);
    cairo_move_to(cr_, x1, y1);
    cairo_line_to(cr_, x2, y2);
    const double a = std::atan2(y2 - y1, x2 - x1), len = std::min(6.0, 0.4 * std::hypot(x2 - x1, y2 - y1));
    cairo_move_to(cr_, x2, y2);
    cairo_line_to(cr_, x2 - len * std::cos(a - 0.4), y2 - len * std::sin(a - 0.4));
    cairo_move_to(cr_, x2, y2);
    cairo_line_to(cr_, x2 - len * std::cos(a + 0.4), y2 - len * std::sin(a + 0.4));
    cairo_stroke(cr_);
  }
  void rectangle(double x, double y, double w, double h, Rgb c) {
    cairo_set_source_rgb(cr_, c.r, c.g, c.b);
    cairo_rectangle(cr_, px(x), py(y + h), w * scale_, h * scale_);
    cairo_fill(cr_);
  }
  void text(double x, double y, const std::string& s, double size_px, Rgb c = {0, 0, 0}) {
    cairo_set_source_rgb(cr_, c.r, c.g, c.b);
    cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr_, size_px);
    cairo_move_to(cr_, px(x), py(y));
    cairo_show_text(cr_, s.c_str());
  }
  void save(const std::string& path) {
    cairo_surface_flush(surface_);
    if (cairo_surface_write_to_png(surface_, path.c_str()) != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error("cannot write " + path);
  }

 private:
  double scale_, margin_, height_mm_;
  cairo_surface_t* surface_;
  cairo_t* cr_;
};

// The specimen as generated: aggregates in stone colours, mastic dark grey,
// air voids white, polygon outlines thin.
inline void specimen_png(const vrut::Specimen& sp, const std::string& path, double scale = 6.0) {
  Canvas c(sp.width, sp.height, scale);
  c.rectangle(0, 0, sp.width, sp.height, {1, 1, 1});
  const double r = sp.disks.radius;
  for (std::size_t i = 0; i < sp.disks.centers.size(); ++i) {
    const int a = sp.disks.aggregate[i];
    c.disk(sp.disks.centers[i].x(), sp.disks.centers[i].y(), r, a >= 0 ? stone(a) : Rgb{0.22, 0.22, 0.22});
  }
  for (const auto& a : sp.placement.aggregates) c.polygon(a.polygon, {0.35, 0.25, 0.15}, 0.8);
  c.save(path);
}

// The section as a scan of it would show it, `pixels_per_mm` to the mm and
// nothing round it: mastic black, stones grey (128), the air voids (the
// lattice sites left empty) white. What vrut-specimen --image reads back
// with --phases mastic,stone,void.
inline void section_png(const vrut::Specimen& sp, const std::string& path, double pixels_per_mm) {
  Canvas c(sp.width, sp.height, pixels_per_mm, 0.0);
  c.rectangle(0, 0, sp.width, sp.height, {0, 0, 0});
  vrut::Placement none;
  std::mt19937_64 unused(1);
  const vrut::DiskPacking sites = vrut::pack_disks(none, sp.width, sp.height, sp.disks.radius, 0.0, unused);
  std::size_t i = 0;
  for (const auto& site : sites.centers) {
    if (i < sp.disks.centers.size() && (sp.disks.centers[i] - site).norm() < 1e-9) {
      ++i;
      continue;
    }
    c.disk(site.x(), site.y(), sp.disks.radius, {1, 1, 1});
  }
  for (const auto& a : sp.placement.aggregates) c.fill_polygon(a.polygon, {128 / 255.0, 128 / 255.0, 128 / 255.0});
  c.save(path);
}

}  // namespace vrut::app::draw
