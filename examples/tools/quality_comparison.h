// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The quality mode of benchmark_remeshing (`--quality`): remeshes each mesh once with CGAL's
// isotropic_remeshing and once per seed with graphcut_isotropic_remeshing, and prints per mesh and
// seed the density, angles, share of poor triangles, distances to the input and times of both,
// with whether ours meets the bars set against CGAL's. With length factors (`--length-factors`),
// both aim at given multiples of the input's mean edge length, and a row per mesh, factor and seed.

#ifndef CGAL_GRAPHCUT_REMESHING_QUALITY_COMPARISON_H
#define CGAL_GRAPHCUT_REMESHING_QUALITY_COMPARISON_H

#include "tool_support.h"

#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <iostream>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace graphcut_remeshing_tools {

// The meshes of the quality comparison when --meshes is not given.
inline const std::vector<std::string>& quality_default_meshes()
{
  static const std::vector<std::string> meshes = {
    "fandisk", "cow",    "triceratops",  "knot",  "handle", "head",         "man",  "camel",
    "lion-head", "helmet", "couplingdown", "joint", "holes",  "ALSTOM_TEST4", "blade"};
  return meshes;
}

// The bars ours must meet against CGAL's result on the same input.
constexpr double quality_max_vertex_ratio = 1.15;  // at most 15 % more vertices
// At a requested length, the vertex count within 15 % of CGAL's either way (issue 24): fewer
// vertices than asked for is then as much a miss as more.
constexpr double quality_max_vertex_deviation = 0.15;
constexpr double quality_max_hausdorff_ratio = 0.7; // 30 % closer to the input, at least
constexpr double quality_poor_angle = 30;           // degrees: a triangle below it is poor
// Degrees: how far the input's edges at least this sharp are from the output's edges at least
// that sharp (issue 23's test of fandisk's sharp lines).
constexpr double quality_input_sharp_angle = 45;
constexpr double quality_output_sharp_angle = 25;
// Passed explicitly rather than left to the default, so that the footnote stays true.
constexpr std::size_t quality_distance_samples = 300000;

struct Quality_options
{
  std::string data_dir;
  std::vector<std::string> meshes = quality_default_meshes();
  std::vector<unsigned int> seeds = {0, 1};
  // graphcut_parameters::resampling of our remesher
  bool resampling = CGAL::Polygon_mesh_processing::internal::Graphcut_remeshing::Remeshing_options().resampling;
  // graphcut_parameters::sharp_angle_bounds of our remesher; none: the mode's default
  std::optional<std::pair<double, double> > sharp_angle_bounds;
  // Positive multiples of the input's mean edge length both remeshers aim at, each in turn; empty:
  // ours chooses its density, CGAL's aims at the mean edge length.
  std::vector<double> length_factors;
};

// The figures of one remeshed output.
struct Remeshing_quality
{
  std::size_t vertices = 0;
  double mean_min_angle = 0;      // degrees
  double mean_max_angle = 0;      // degrees
  double min_angle = 0;           // degrees, the smallest of all triangles
  double max_angle = 0;           // degrees, the largest
  double poor_percentage = 0;     // share of triangles with an angle below quality_poor_angle
  double hausdorff = 0;           // ratio to the input's bounding-box diagonal
  double rms = 0;                 // the same
  double sharp_line_distance = 0; // the same; see quality_input_sharp_angle
  double seconds = 0;             // the remeshing call alone
};

struct Quality_row
{
  std::string mesh;
  unsigned int seed = 0;
  std::size_t input_vertices = 0;
  Remeshing_quality ours, cgal;
  double length_factor = 0; // of Quality_options::length_factors; 0: ours without a target length
};

// Whether some row aims at a requested length: the table and the JSON then say which.
inline bool has_length_factors(const std::vector<Quality_row>& rows)
{
  return std::any_of(rows.begin(), rows.end(), [](const Quality_row& r) { return r.length_factor > 0; });
}

// The percentage of faces of `mesh` whose smallest angle is below `threshold_degrees`. The
// quality report gives the mean only, which a few needles barely move.
inline double poor_triangle_percentage(const Mesh& mesh, double threshold_degrees)
{
  namespace GR = CGAL::Polygon_mesh_processing::internal::Graphcut_remeshing;
  std::size_t poor = 0, total = 0;
  for(Mesh::Face_index f : faces(mesh))
  {
    const Mesh::Halfedge_index h = mesh.halfedge(f);
    const auto angles = GR::triangle_angles(GR::to_vector(mesh.point(mesh.source(h))),
                                            GR::to_vector(mesh.point(mesh.target(h))),
                                            GR::to_vector(mesh.point(mesh.target(mesh.next(h)))));
    if(GR::to_degrees((std::min)({angles[0], angles[1], angles[2]})) < threshold_degrees)
      ++poor;
    ++total;
  }
  return total == 0 ? 0 : 100.0 * double(poor) / double(total);
}

inline Remeshing_quality measure_remeshing(const Mesh& input, const Mesh& output, double seconds)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  Remeshing_quality q;
  const PMP::Mesh_quality_report report = PMP::mesh_quality_report(output);
  q.vertices = report.number_of_vertices;
  q.mean_min_angle = report.mean_min_angle;
  q.mean_max_angle = report.mean_max_angle;
  q.min_angle = report.min_angle;
  q.max_angle = report.max_angle;
  q.poor_percentage = poor_triangle_percentage(output, quality_poor_angle);
  const PMP::Relative_surface_distance d = PMP::relative_surface_distance(
    input, output, CGAL::parameters::number_of_points_on_faces(quality_distance_samples));
  q.hausdorff = d.hausdorff;
  q.rms = d.rms;
  q.sharp_line_distance =
    PMP::relative_sharp_edge_distance(input, output, quality_input_sharp_angle, quality_output_sharp_angle);
  q.seconds = seconds;
  return q;
}

// The names of the bars the row misses, in a fixed order; empty when it meets them all. The
// comparisons use the unrounded figures, so a missed bar may look like a tie in the table.
inline std::vector<std::string> missed_quality_bars(const Quality_row& row)
{
  const Remeshing_quality &o = row.ours, &c = row.cgal;
  std::vector<std::string> missed;
  const double ours_vertices = double(o.vertices), cgal_vertices = double(c.vertices);
  if(row.length_factor > 0 ? std::abs(ours_vertices - cgal_vertices) > quality_max_vertex_deviation * cgal_vertices
                           : ours_vertices > quality_max_vertex_ratio * cgal_vertices)
    missed.push_back("density");
  if(o.mean_min_angle < c.mean_min_angle)
    missed.push_back("angle");
  if(o.poor_percentage > c.poor_percentage)
    missed.push_back("poor");
  if(o.hausdorff > quality_max_hausdorff_ratio * c.hausdorff)
    missed.push_back("hausdorff");
  return missed;
}

inline std::string quality_bars_text(const Quality_row& row)
{
  const std::vector<std::string> missed = missed_quality_bars(row);
  if(missed.empty())
    return "met";
  std::string text = "missed ";
  for(std::size_t i = 0; i < missed.size(); ++i)
    text += (i ? "," : "") + missed[i];
  return text;
}

// "ours/cgal" with fixed widths, so that the slashes line up down a column.
inline std::string quality_pair(double ours, double cgal, int width_ours, int width_cgal, int digits)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << std::setw(width_ours) << ours << '/'
    << std::setw(width_cgal) << cgal;
  return s.str();
}

// The bars and units under the table; `at_lengths`: the rows aim at requested lengths.
inline void write_quality_notes(std::ostream& out, std::size_t met, std::size_t rows, bool at_lengths)
{
  out << '\n' << met << " of " << rows << " rows meet every bar: ";
  if(at_lengths)
    out << "|V ours - V cgal| <= " << quality_max_vertex_deviation << " x V cgal";
  else
    out << "V ours <= " << quality_max_vertex_ratio << " x V cgal";
  out << " (density), min ours >= min cgal (angle), <" << quality_poor_angle << " % ours <= <"
      << quality_poor_angle << " % cgal (poor), H ours <= " << quality_max_hausdorff_ratio
      << " x H cgal (hausdorff)\n";
  if(at_lengths)
    out << "L/mean: the target edge length of both remeshers, in the input's mean edge lengths\n";
  out << "min, max: mean minimum and maximum angles, degrees; <" << quality_poor_angle
      << " %: share of triangles with an angle below " << quality_poor_angle << " degrees; s: seconds of the "
      << "remeshing call alone\n"
      << "H, RMS: distances to the input, x1e-3 of the input's bounding-box diagonal, "
      << quality_distance_samples / 1000 << "k samples a side\n"
      << "sharp: largest distance from the input's edges with a dihedral angle >= " << quality_input_sharp_angle
      << " degrees to the output's edges >= " << quality_output_sharp_angle << " degrees, the same unit\n";
}

// The L/mean column is there only when rows aim at requested lengths, so that the plain
// comparison's table stays as it was.
inline void write_quality_table(std::ostream& out, const std::vector<Quality_row>& rows)
{
  const bool at_lengths = has_length_factors(rows);
  const int seed_width = at_lengths ? 5 : 4; // keeps a space after "L/mean"
  out << std::left << std::setw(16) << "mesh" << std::right;
  if(at_lengths)
    out << std::setw(7) << "L/mean";
  out << std::setw(seed_width) << "seed" << std::setw(6) << "V in" << std::setw(8) << "V ours" << std::setw(8)
      << "V cgal" << std::setw(15) << "min ours/cgal" << std::setw(15) << "max ours/cgal" << std::setw(17)
      << "worst ours/cgal" << std::setw(15) << "widest ours/cgal" << std::setw(17)
      << "<30 % ours/cgal" << std::setw(13) << "H ours/cgal" << std::setw(15) << "RMS ours/cgal" << std::setw(17)
      << "sharp ours/cgal" << std::setw(14) << "s ours/cgal"
      << "  bars\n";
  std::size_t met = 0;
  for(const Quality_row& r : rows)
  {
    const Remeshing_quality &o = r.ours, &c = r.cgal;
    out << std::left << std::setw(16) << r.mesh << std::right;
    if(at_lengths)
      out << std::setw(7) << r.length_factor;
    out << std::setw(seed_width) << r.seed << std::setw(6) << r.input_vertices << std::setw(8) << o.vertices
        << std::setw(8) << c.vertices << std::setw(15) << quality_pair(o.mean_min_angle, c.mean_min_angle, 5, 6, 2)
        << std::setw(15) << quality_pair(o.mean_max_angle, c.mean_max_angle, 5, 6, 2) << std::setw(17)
        << quality_pair(o.min_angle, c.min_angle, 5, 6, 2) << std::setw(15)
        << quality_pair(o.max_angle, c.max_angle, 6, 6, 2) << std::setw(17)
        << quality_pair(o.poor_percentage, c.poor_percentage, 5, 5, 1) << std::setw(13)
        << quality_pair(1e3 * o.hausdorff, 1e3 * c.hausdorff, 5, 5, 2) << std::setw(15)
        << quality_pair(1e3 * o.rms, 1e3 * c.rms, 5, 5, 3) << std::setw(17)
        << quality_pair(1e3 * o.sharp_line_distance, 1e3 * c.sharp_line_distance, 6, 6, 3) << std::setw(14)
        << quality_pair(o.seconds, c.seconds, 6, 5, 2) << "  " << quality_bars_text(r) << '\n';
    met += missed_quality_bars(r).empty() ? 1 : 0;
  }
  write_quality_notes(out, met, rows.size(), at_lengths);
}

inline void write_quality_json(std::ostream& out, const Remeshing_quality& q)
{
  out << "{\"vertices\": " << q.vertices << ", \"mean_min_angle\": " << json_number(q.mean_min_angle)
      << ", \"mean_max_angle\": " << json_number(q.mean_max_angle) << ", \"min_angle\": " << json_number(q.min_angle)
      << ", \"max_angle\": " << json_number(q.max_angle)
      << ", \"poor_percent\": " << json_number(q.poor_percentage)
      << ", \"hausdorff\": " << json_number(q.hausdorff) << ", \"rms\": " << json_number(q.rms)
      << ", \"sharp_line_distance\": " << json_number(q.sharp_line_distance)
      << ", \"seconds\": " << json_number(q.seconds) << "}";
}

// A mesh name as a JSON string: names come from the command line, so they may hold anything.
inline std::string quality_json_string(const std::string& text)
{
  std::string out = "\"";
  for(char c : text)
  {
    if(static_cast<unsigned char>(c) < 0x20)
      continue; // control characters are dropped rather than escaped: a name never needs them
    if(c == '"' || c == '\\')
      out += '\\';
    out += c;
  }
  return out + "\"";
}

// Distances are plain ratios to the diagonal here, as in the timing mode's JSON. The fields of
// requested lengths are there only for rows that aim at one, as the table's column.
inline void write_quality_json(std::ostream& out, const std::vector<Quality_row>& rows)
{
  out << "{\"poor_angle\": " << json_number(quality_poor_angle)
      << ", \"distance_samples\": " << quality_distance_samples;
  if(has_length_factors(rows))
    out << ", \"max_vertex_deviation\": " << json_number(quality_max_vertex_deviation);
  out << ",\n \"rows\": [";
  for(std::size_t i = 0; i < rows.size(); ++i)
  {
    const Quality_row& r = rows[i];
    const std::vector<std::string> missed = missed_quality_bars(r);
    out << (i ? ",\n  " : "\n  ") << "{\"mesh\": " << quality_json_string(r.mesh);
    if(r.length_factor > 0)
      out << ", \"length_factor\": " << json_number(r.length_factor);
    out << ", \"seed\": " << r.seed << ", \"input_vertices\": " << r.input_vertices << ",\n   \"ours\": ";
    write_quality_json(out, r.ours);
    out << ",\n   \"cgal\": ";
    write_quality_json(out, r.cgal);
    out << ",\n   \"bars_met\": " << (missed.empty() ? "true" : "false") << ", \"missed\": [";
    for(std::size_t k = 0; k < missed.size(); ++k)
      out << (k ? ", " : "") << '"' << missed[k] << '"';
    out << "]}";
  }
  out << "]}\n";
}

// Our remesher with the options' parameters and `seed`, timed; aiming at `target`, in the mesh's
// units, when it is positive. The overload with a target re-samples whatever
// graphcut_parameters::resampling says, so options.resampling is not passed on there.
inline double remesh_with_ours(Mesh& mesh, const Quality_options& options, unsigned int seed, double target)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  namespace GP = PMP::graphcut_parameters;
  const std::pair<double, double> bounds = options.sharp_angle_bounds.value_or(
    CGAL::Polygon_mesh_processing::internal::Graphcut_remeshing::Remeshing_options().default_sharp_angle_bounds(
      options.resampling, target > 0));
  const auto start = std::chrono::steady_clock::now();
  if(target > 0)
    PMP::graphcut_isotropic_remeshing(faces(mesh), target, mesh,
                                      GP::combine(CGAL::parameters::random_seed(seed), GP::sharp_angle_bounds(bounds)));
  else
    PMP::graphcut_isotropic_remeshing(mesh, GP::combine(CGAL::parameters::random_seed(seed),
                                                        GP::resampling(options.resampling), GP::sharp_angle_bounds(bounds)));
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Remeshes a copy of `input` with `remesh(copy)`, which returns the seconds it timed, and measures
// the result. Both remeshers may leave removed elements in the mesh; the figures count live ones
// only, so they are collected outside the timed part.
template <typename Remesh>
Remeshing_quality remesh_and_measure(const Mesh& input, const std::string& label, const Remesh& remesh)
{
  std::cerr << label << " ..." << std::flush;
  Mesh output = input;
  const double seconds = remesh(output);
  output.collect_garbage();
  std::ostringstream time;
  time << std::fixed << std::setprecision(2) << seconds;
  std::cerr << ' ' << time.str() << " s, measuring ..." << std::flush;
  const Remeshing_quality quality = measure_remeshing(input, output, seconds);
  std::cerr << " done\n";
  return quality;
}

// Runs the comparison, appending a row per mesh, length factor and seed to `rows` as soon as it is
// complete, so that the caller still has the finished rows when a later mesh throws.
// `remesh_with_cgal(mesh, target)` remeshes in place aiming at `target`, in the mesh's units, and
// returns the seconds it timed: the timing mode's CGAL run, so that both modes measure the same
// thing. CGAL's result does not depend on our seed, so it runs once a mesh and factor.
template <typename CgalRemesh>
void run_quality_comparison(const Quality_options& options, const CgalRemesh& remesh_with_cgal,
                            std::vector<Quality_row>& rows)
{
  // Without factors, one pass with factor 0: ours without a target, CGAL's at the mean edge length.
  const std::vector<double> factors =
    options.length_factors.empty() ? std::vector<double>{0} : options.length_factors;
  for(const std::string& name : options.meshes)
  {
    std::cerr << name << ": reading ..." << std::flush;
    const Mesh input = read_mesh(options.data_dir + "/" + name + ".off", true);
    const double mean = mean_edge_length(input);
    std::cerr << ' ' << num_vertices(input) << " vertices, mean edge length " << mean << '\n';
    for(double factor : factors)
    {
      std::ostringstream at;
      at << name;
      if(factor > 0)
        at << ", L = " << factor << " x mean";
      const double cgal_target = (factor > 0 ? factor : 1) * mean;
      const Remeshing_quality cgal = remesh_and_measure(
        input, at.str() + ": cgal", [&](Mesh& mesh) { return remesh_with_cgal(mesh, cgal_target); });
      for(unsigned int seed : options.seeds)
      {
        const Remeshing_quality ours =
          remesh_and_measure(input, at.str() + ": ours, seed " + std::to_string(seed),
                             [&](Mesh& mesh) { return remesh_with_ours(mesh, options, seed, factor * mean); });
        rows.push_back(Quality_row{name, seed, num_vertices(input), ours, cgal, factor});
      }
    }
  }
}

} // namespace graphcut_remeshing_tools

#endif // CGAL_GRAPHCUT_REMESHING_QUALITY_COMPARISON_H
