#pragma once
// vrut-rutting's pictures and files: the rut forming, the displacement
// field, the final state for ParaView, and the JSON forms of its numbers.
#include "draw.hpp"

#include <vrut/analysis/standard_ds.hpp>
#include <vrut/analysis/statistics.hpp>
#include <vrut/io/vtk.hpp>
#include <vrut/protocol/rutting/result.hpp>
#include <vrut/specimen/specimen.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace vrut::app {

// The deformed specimen at one moment: disks where they are, stones and
// mastic in their colours, the plate in red.
inline void snapshot_panel(draw::Canvas& c, const vrut::Specimen& sp, const vrut::RuttingSnapshot& s, double y_offset_mm,
                    const vrut::RuttingResult& res, double plate_y_mm) {
  const double r = sp.disks.radius;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const int a = sp.disks.aggregate[i];
    c.disk(s.x[i] * 1e3, s.y[i] * 1e3 + y_offset_mm, r, a >= 0 ? draw::stone(a) : draw::Rgb{0.22, 0.22, 0.22});
  }
  c.rectangle(res.plate_x0 * 1e3, plate_y_mm + y_offset_mm, (res.plate_x1 - res.plate_x0) * 1e3, 1.5,
              {0.8, 0.1, 0.1});
}

// rut_forming.png: the specimen at 20, 40 and 60 min.
inline void rut_forming_png(const vrut::Specimen& sp, const vrut::RuttingResult& res, double test_minutes,
                     const std::string& path) {
  const double W = sp.width, H = sp.height;
  const double panel = H + 12.0;  // a strip for the label above each panel
  draw::Canvas c(W, 3 * panel, 5.0);
  const double plate_top = res.plate_y_final * 1e3;
  const double final_mm = res.samples.back().deformation * 1e3;
  for (std::size_t k = 0; k < res.snapshots.size(); ++k) {
    const double offset = (2 - static_cast<double>(k)) * panel;
    const auto& s = res.snapshots[k];
    // Plate height at this moment: from the deformation curve.
    const double when = s.fraction * test_minutes;
    double def = final_mm;
    for (const auto& smp : res.samples)
      if (smp.minutes >= when) { def = smp.deformation * 1e3; break; }
    snapshot_panel(c, sp, s, offset, res, plate_top + final_mm - def);
    char label[128];
    std::snprintf(label, sizeof label, "%.0f min: rut %.2f mm", when, def);
    c.text(2.0, offset + H + 5.0, label, 16.0);
  }
  c.save(path);
}

// displacement.png: the displacement field at the end, colour and arrows.
inline void displacement_png(const vrut::Specimen& sp, const vrut::RuttingResult& res, const std::string& path) {
  const double W = sp.width, H = sp.height;
  const auto& end = res.snapshots.back();
  draw::Canvas c(W, H + 12.0, 6.0);
  double dmax = 1e-12;
  for (std::size_t i = 0; i < end.x.size(); ++i) dmax = std::max(dmax, std::hypot(end.dx[i], end.dy[i]));
  for (std::size_t i = 0; i < end.x.size(); ++i)
    c.disk(end.x[i] * 1e3, end.y[i] * 1e3, sp.disks.radius, draw::heat(std::hypot(end.dx[i], end.dy[i]) / dmax));
  // Vectors on a coarse grid, scaled so the largest is 8 mm long.
  const double every = std::max(1.0, std::floor(end.x.size() / 600.0));
  for (std::size_t i = 0; i < end.x.size(); i += static_cast<std::size_t>(every))
    c.arrow(end.x[i] * 1e3, end.y[i] * 1e3, end.dx[i] / dmax * 8.0, end.dy[i] / dmax * 8.0, {0, 0, 0}, 1.0);
  char label[160];
  std::snprintf(label, sizeof label, "|u| at the end: 0 (blue) to %.2f mm (red); longest arrow 8 mm", dmax * 1e3);
  c.text(2.0, H + 6.0, label, 14.0);
  c.save(path);
}

// final.vtk: final positions, displacement, velocity, group.
inline void final_vtk(const vrut::Specimen& sp, const vrut::RuttingResult& res, const std::string& path) {
  const auto& end = res.snapshots.back();
  std::vector<double> group(res.group.begin(), res.group.end()), radius(end.x.size(), sp.disks.radius * 1e-3);
  std::vector<std::pair<double, double>> disp, vel;
  for (std::size_t i = 0; i < end.x.size(); ++i) {
    disp.emplace_back(end.dx[i], end.dy[i]);
    vel.emplace_back(res.vx[i], res.vy[i]);
  }
  vrut::VtkPointData data;
  data.scalars = {{"radius", radius}, {"group", group}};
  data.vectors = {{"displacement", disp}, {"velocity", vel}};
  vrut::write_vtk_disks(path, "vrut rutting final state (m); group 0 mastic, 1 aggregate", end.x, end.y, data);
}

// A DS as the standard reports it (analysis/standard_ds.hpp): the value, and
// whether it is only a lower bound ("> 6000", or our "above N").
inline nlohmann::json standard_ds_json(const vrut::ReportedDS& d) {
  return {{"passes_per_mm", d.value}, {"censored", d.censored}};
}

inline nlohmann::json statistics_json(const vrut::SampleStatistics& s) {
  nlohmann::json j;
  j["n"] = s.n;
  j["mean"] = s.mean;
  j["sd"] = s.sd;
  j["ci"] = {s.ci_low, s.ci_high};
  j["confidence"] = s.confidence;
  j["median"] = s.median;
  j["min"] = s.min;
  j["max"] = s.max;
  return j;
}

}  // namespace vrut::app
