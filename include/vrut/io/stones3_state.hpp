#pragma once
// A 3D placement's stones as a checkpoint item, so that --resume takes the
// stones the run began with instead of placing them again: a compacted 3#
// specimen costs about 18 minutes to place, every time. Written with the
// checkpoint's StateWriter (each number's bytes as they are), so the stones
// read back are the same doubles and the specimen built on them the same
// specimen, bit for bit. Host-only; needs nlohmann_json.
#include <vrut/io/checkpoint.hpp>
#include <vrut/specimen/placement3.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace vrut {

inline nlohmann::json stones3_state(const Placement3& p) {
  std::vector<int> size_class, vertex_count, plane_count;
  std::vector<double> diameter, vertices, planes, centroid, volume, reach;
  for (const PlacedStone3& s : p.stones) {
    size_class.push_back(s.size_class);
    diameter.push_back(s.diameter);
    vertex_count.push_back(static_cast<int>(s.shape.vertices.size()));
    for (const Point3& v : s.shape.vertices) vertices.insert(vertices.end(), {v.x(), v.y(), v.z()});
    plane_count.push_back(static_cast<int>(s.shape.planes.size()));
    for (const auto& q : s.shape.planes) planes.insert(planes.end(), {q[0], q[1], q[2], q[3]});
    centroid.insert(centroid.end(), {s.shape.centroid.x(), s.shape.centroid.y(), s.shape.centroid.z()});
    volume.push_back(s.shape.volume);
    reach.push_back(s.shape.reach);
  }
  StateWriter w;
  w.vector("size_class", size_class);
  w.vector("diameter", diameter);
  w.vector("vertex_count", vertex_count);
  w.vector("vertices", vertices);
  w.vector("plane_count", plane_count);
  w.vector("planes", planes);
  w.vector("centroid", centroid);
  w.vector("volume", volume);
  w.vector("reach", reach);
  w.value("depth", p.depth);
  w.value("target_fraction", p.target_fraction);
  w.value("achieved_fraction", p.achieved_fraction);
  w.value("jammed", p.jammed);
  w.value("compaction_steps", p.compaction_steps);
  w.value("pairs_within_clearance", p.pairs_within_clearance);
  w.value("stones_within_clearance_of_a_wall", p.stones_within_clearance_of_a_wall);
  return w.state();
}

// The placement back from stones3_state; source names the file in errors.
// Counts that do not add up are refused as a damaged checkpoint.
inline Placement3 placement_from_stones3_state(const nlohmann::json& state, const std::string& source) {
  StateReader r(state, source);
  std::vector<int> size_class, vertex_count, plane_count;
  std::vector<double> diameter, vertices, planes, centroid, volume, reach;
  r.vector("size_class", size_class);
  r.vector("diameter", diameter);
  r.vector("vertex_count", vertex_count);
  r.vector("vertices", vertices);
  r.vector("plane_count", plane_count);
  r.vector("planes", planes);
  r.vector("centroid", centroid);
  r.vector("volume", volume);
  r.vector("reach", reach);
  Placement3 p;
  r.value("depth", p.depth);
  r.value("target_fraction", p.target_fraction);
  r.value("achieved_fraction", p.achieved_fraction);
  r.value("jammed", p.jammed);
  r.value("compaction_steps", p.compaction_steps);
  // Optional: a checkpoint of this format and version written by an older build has none (its stones settled).
  if (state.contains("pairs_within_clearance")) {
    r.value("pairs_within_clearance", p.pairs_within_clearance);
    r.value("stones_within_clearance_of_a_wall", p.stones_within_clearance_of_a_wall);
  }
  const std::size_t n = size_class.size();
  std::size_t all_vertices = 0, all_planes = 0;
  for (std::size_t i = 0; i < vertex_count.size(); ++i) all_vertices += static_cast<std::size_t>(vertex_count[i]);
  for (std::size_t i = 0; i < plane_count.size(); ++i) all_planes += static_cast<std::size_t>(plane_count[i]);
  if (diameter.size() != n || vertex_count.size() != n || plane_count.size() != n || volume.size() != n ||
      reach.size() != n || centroid.size() != 3 * n || vertices.size() != 3 * all_vertices ||
      planes.size() != 4 * all_planes)
    throw CheckpointError(source + ": the stones' items do not agree in their counts (damaged?)");
  std::size_t v = 0, q = 0;
  p.stones.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    PlacedStone3& s = p.stones[i];
    s.size_class = size_class[i];
    s.diameter = diameter[i];
    for (int k = 0; k < vertex_count[i]; ++k, v += 3) s.shape.vertices.emplace_back(vertices[v], vertices[v + 1], vertices[v + 2]);
    for (int k = 0; k < plane_count[i]; ++k, q += 4) s.shape.planes.emplace_back(planes[q], planes[q + 1], planes[q + 2], planes[q + 3]);
    s.shape.centroid = Point3(centroid[3 * i], centroid[3 * i + 1], centroid[3 * i + 2]);
    s.shape.volume = volume[i];
    s.shape.reach = reach[i];
  }
  return p;
}

}  // namespace vrut
