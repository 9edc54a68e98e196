// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// benchmark_remeshing [options]: times graphcut_isotropic_remeshing against CGAL's
// isotropic_remeshing on CGAL's sample meshes and on a large mesh built from bear.off, and prints
// the median times, the peak resident memory of each run and the quality of the results. With
// --quality it compares instead the quality of both results, per mesh and seed, against bars; with
// --length-factors too, both remesh at given multiples of the input's mean edge length. With
// --corpus it times both on every sample mesh up to a size.

#include "quality_comparison.h"
#include "tool_support.h"

#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Random.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/version.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/resource.h>
#endif
#ifdef __GLIBC__
#include <malloc.h>
#endif

#ifndef GRAPHCUT_REMESHING_DATA_DIR
#define GRAPHCUT_REMESHING_DATA_DIR "data/meshes"
#endif

namespace PMP = CGAL::Polygon_mesh_processing;
namespace tools = graphcut_remeshing_tools;

namespace {

using Mesh = tools::Mesh;
using Vector = tools::Kernel::Vector_3;

const char* const program = "benchmark_remeshing";
const char* const large_mesh_name = "bear_loop2_jitter";
const std::vector<std::string> all_meshes = {"fandisk", "cow", "triceratops", "bear", large_mesh_name};
// The tangential jitter of the large mesh is seeded, so every run benchmarks the same mesh.
const unsigned int jitter_seed = 2026;
const std::size_t corpus_max_vertices = 30000;
const double cgal_sharp_angle = 35;
const unsigned int cgal_iterations = 5;

std::string quality_usage()
{
  // The default list, wrapped to the width of the rest of the help.
  std::string meshes, line;
  for(const auto& m : tools::quality_default_meshes())
  {
    if(!line.empty() && line.size() + m.size() + 1 > 50)
    {
      meshes += line + ",\n" + std::string(26, ' ');
      line.clear();
    }
    line += (line.empty() ? "" : ",") + m;
  }
  meshes += line;
  const PMP::internal::Graphcut_remeshing::Remeshing_options defaults;
  std::ostringstream bounds;
  bounds << defaults.sharp_angle_bounds.first << ' ' << defaults.sharp_angle_bounds.second << ", with --no-resampling or\n"
         << "                          --length-factors " << defaults.paper_sharp_angle_bounds.first << ' ' << defaults.paper_sharp_angle_bounds.second;
  return "\n"
         "usage: benchmark_remeshing --quality [--meshes LIST] [--seeds LIST] [--no-resampling]\n"
         "                                     [--sharp-angle LOW HIGH] [--length-factors LIST]\n"
         "                                     [--data DIR] [--json FILE]\n"
         "\n"
         "Compares the quality of graphcut_isotropic_remeshing (defaults, each seed) with that of CGAL's\n"
         "isotropic_remeshing (as above, run once a mesh): a row per mesh and seed with the vertex\n"
         "counts, mean minimum and maximum angles, the smallest and largest angles, the share of\n"
         "triangles with an angle below 30\n"
         "degrees, Hausdorff and RMS distances to the input (x1e-3 of its bounding-box diagonal,\n"
         "300k samples a side), the seconds of each remeshing, and whether ours meets the bars: at\n"
         "most 1.15 times cgal's vertices, a mean minimum angle >= cgal's, a share below 30 degrees\n"
         "<= cgal's and a Hausdorff distance <= 0.7 times cgal's. Exits with 0 even when bars are\n"
         "missed.\n"
         "\n"
         "  --quality               switch to this mode\n"
         "  --meshes LIST           comma-separated names of files <name>.off in the data directory\n"
         "                          (default " +
         meshes +
         ")\n"
         "  --seeds LIST            comma-separated random seeds of our remesher (default 0,1)\n"
         "  --no-resampling         our remesher with graphcut_parameters::resampling(false), the\n"
         "                          paper's connectivity (default: re-sampling, as the remesher's)\n"
         "  --sharp-angle LOW HIGH  our remesher's sharp-edge hysteresis bounds, degrees (default " +
         bounds.str() +
         ")\n"
         "  --length-factors LIST   comma-separated positive factors f: both remeshers aim at f times\n"
         "                          the input's mean edge length, ours through\n"
         "                          graphcut_isotropic_remeshing(faces(mesh), target, mesh, np)\n"
         "                          (re-sampling on, whatever --no-resampling says), CGAL's once a mesh\n"
         "                          and factor; a row per mesh, factor and seed, with a column L/mean,\n"
         "                          and the density bar becomes |V ours - V cgal| <= 0.15 times cgal's\n"
         "                          (default none: ours without a target, as above)\n"
         "  --data DIR              as above\n"
         "  --json FILE             also write the rows as JSON (distances there are plain ratios\n"
         "                          to the diagonal, not x1e-3; with --length-factors each row has\n"
         "                          its \"length_factor\")\n";
}

std::string corpus_usage()
{
  return "\n"
         "usage: benchmark_remeshing --corpus [--max-vertices N] [--repetitions N] [--data DIR]\n"
         "                                    [--json FILE]\n"
         "\n"
         "Times both remeshers, as above, on every OFF, OBJ, PLY and STL file of the data directory\n"
         "that reads as a valid triangle mesh (after the tools' soup repair) of at most N vertices,\n"
         "prints the table above for them, then the median, 90th percentile and largest ratio of the\n"
         "times, and the files left out with the reason.\n"
         "\n"
         "  --corpus                switch to this mode\n"
         "  --max-vertices N        the largest input to time (default " +
         std::to_string(corpus_max_vertices) +
         ")\n"
         "  --repetitions N         timed runs of each method on each mesh (default 1)\n"
         "  --data DIR, --json FILE as above\n";
}

std::string usage()
{
  return std::string(
           "usage: benchmark_remeshing [options]\n"
           "\n"
           "Times graphcut_isotropic_remeshing (defaults, seed 0) against CGAL's isotropic_remeshing\n"
           "(target length the input's mean edge length, 5 iterations, edges of 35 degrees or more\n"
           "constrained) on CGAL's sample meshes and on bear_loop2_jitter, bear.off Loop-subdivided\n"
           "twice and jittered in the tangent planes. Prints the median times, the peak resident\n"
           "memory of each run and the quality of the results; progress goes to stderr.\n"
           "\n"
           "  --data DIR              directory holding <name>.off\n"
           "                          (default ") +
         GRAPHCUT_REMESHING_DATA_DIR +
         ")\n"
         "  --meshes LIST           comma-separated subset of fandisk,cow,triceratops,bear,\n"
         "                          bear_loop2_jitter (default all five)\n"
         "  --methods LIST          comma-separated subset of ours,cgal (default ours,cgal)\n"
         "  --repetitions N         timed runs of each method on each sample mesh, the median\n"
         "                          is reported (default 3)\n"
         "  --large-repetitions N   the same for bear_loop2_jitter (default 1)\n"
         "  --skip-large            leave out bear_loop2_jitter\n"
         "  --json FILE             also write the figures and the machine as JSON (Hausdorff\n"
         "                          distances there are plain ratios to the diagonal, not x1e-3)\n"
         "  --help                  print this help\n" +
         corpus_usage() + quality_usage();
}

// ---------------------------------------------------------------------------------------------
// Peak resident memory

struct Peak_memory
{
  // Whether /proc/self/clear_refs resets the high-water mark; otherwise the figures are the
  // process's peak since it started.
  bool per_run = false;
};

#ifdef __linux__
bool reset_high_water_mark()
{
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return bool(out);
}

// A "Key:   1234 kB" line of /proc/self/status, in kB; 0 if absent.
double status_kb(const std::string& key)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  while(std::getline(in, line))
  {
    if(line.compare(0, key.size() + 1, key + ":") == 0)
      return std::atof(line.c_str() + key.size() + 1);
  }
  return 0;
}
#endif

double process_peak_kb()
{
#if defined(__unix__) || defined(__APPLE__)
  rusage usage_now;
  if(getrusage(RUSAGE_SELF, &usage_now) != 0)
    return 0;
#ifdef __APPLE__
  return double(usage_now.ru_maxrss) / 1024; // bytes there
#else
  return double(usage_now.ru_maxrss);
#endif
#else
  return 0;
#endif
}

// Called before a run; returns the resident size the run starts from (kB, 0 when unknown).
double start_peak_measurement(Peak_memory& memory)
{
#ifdef __GLIBC__
  // Hand freed heap back to the system, so that the run's peak starts from what is alive.
  malloc_trim(0);
#endif
#ifdef __linux__
  memory.per_run = reset_high_water_mark();
  return status_kb("VmRSS");
#else
  memory.per_run = false;
  return 0;
#endif
}

double peak_kb(const Peak_memory& memory)
{
#ifdef __linux__
  if(memory.per_run)
    return status_kb("VmHWM");
#endif
  (void)memory;
  return process_peak_kb();
}

// ---------------------------------------------------------------------------------------------
// The machine

struct Machine
{
  std::string cpu = "unknown";
  unsigned int hardware_threads = 0;
  std::string compiler;
  std::string cgal = CGAL_VERSION_STR;
  bool tbb = false;
};

Machine describe_machine()
{
  Machine m;
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while(std::getline(in, line))
  {
    if(line.compare(0, 10, "model name") == 0)
    {
      const std::size_t colon = line.find(':');
      if(colon != std::string::npos)
      {
        const std::size_t start = line.find_first_not_of(" \t", colon + 1);
        m.cpu = start == std::string::npos ? "" : line.substr(start);
      }
      break;
    }
  }
  m.hardware_threads = std::thread::hardware_concurrency();
#if defined(__GNUC__) && !defined(__clang__)
  m.compiler = std::string("GCC ") + __VERSION__;
#elif defined(__VERSION__)
  m.compiler = __VERSION__;
#else
  m.compiler = "unknown";
#endif
#ifdef CGAL_LINKED_WITH_TBB
  m.tbb = true;
#endif
  return m;
}

// ---------------------------------------------------------------------------------------------
// Meshes

// Moves every vertex in the tangent plane of its area-weighted normal by a random vector no longer
// than a quarter of its shortest incident edge. The displacements all come from the unmoved
// positions, so the result does not depend on the order of the vertices.
void tangential_jitter(Mesh& mesh, unsigned int seed)
{
  CGAL::Random rng(seed);
  std::vector<std::pair<Mesh::Vertex_index, Vector>> moves;
  moves.reserve(num_vertices(mesh));
  for(auto v : vertices(mesh))
  {
    // Drawn first, for every vertex, so that a vertex left in place does not shift the later draws.
    const double angle = rng.get_double(0, 2 * CGAL_PI);
    const double radius = std::sqrt(rng.get_double(0, 1)); // uniform over the disc
    if(halfedge(v, mesh) == Mesh::null_halfedge())
      continue;
    const auto& p = mesh.point(v);
    Vector normal(0, 0, 0);
    double shortest = -1;
    for(auto h : halfedges_around_target(halfedge(v, mesh), mesh))
    {
      const double length = std::sqrt(CGAL::squared_distance(p, mesh.point(source(h, mesh))));
      shortest = shortest < 0 ? length : (std::min)(shortest, length);
      if(is_border(h, mesh))
        continue;
      // The cross product's length is twice the face's area: the sum is area-weighted.
      const auto& q = mesh.point(source(h, mesh));
      const auto& r = mesh.point(target(next(h, mesh), mesh));
      normal = normal + CGAL::cross_product(q - p, r - p);
    }
    const double normal_length = std::sqrt(normal.squared_length());
    if(!(normal_length > 0) || !(shortest > 0))
      continue;
    normal = normal / normal_length;
    // Any vector not parallel to the normal spans the tangent plane with it.
    const Vector axis = std::abs(normal.x()) < 0.5 ? Vector(1, 0, 0)
                        : std::abs(normal.y()) < 0.5 ? Vector(0, 1, 0) : Vector(0, 0, 1);
    Vector u = CGAL::cross_product(normal, axis);
    u = u / std::sqrt(u.squared_length());
    const Vector w = CGAL::cross_product(normal, u);
    const double length = 0.25 * shortest * radius;
    moves.emplace_back(v, length * (std::cos(angle) * u + std::sin(angle) * w));
  }
  for(const auto& [v, d] : moves)
    mesh.point(v) = mesh.point(v) + d;
}

Mesh build_large_mesh(const std::string& data_dir)
{
  Mesh mesh = tools::read_mesh(data_dir + "/bear.off", true);
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(2));
  tangential_jitter(mesh, jitter_seed);
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// Runs

struct Method_result
{
  bool done = false;
  std::vector<double> seconds;
  double median_seconds = 0;
  double peak_kb = 0;     // the largest over the repetitions
  double baseline_kb = 0; // resident size when that run started
  std::size_t output_vertices = 0;
  double mean_min_angle = 0;
  double mean_max_angle = 0;
  double min_angle = 0;    // degrees
  double poor_percent = 0; // share of triangles with an angle below tools::quality_poor_angle
  double hausdorff = 0;    // relative to the input's bounding-box diagonal
};

struct Mesh_result
{
  std::string name;
  std::size_t input_vertices = 0;
  double input_min_angle = 0;        // degrees
  std::size_t input_sharp_edges = 0; // of a dihedral angle of cgal_sharp_angle or more
  std::size_t input_border_edges = 0;
  std::size_t repetitions = 0;
  Method_result ours, cgal;
};

double median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  if(n == 0)
    return 0;
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The input's smallest angle and its sharp and border edges, which the corpus's bars on the
// smallest angle depend on.
void describe_input(const Mesh& input, Mesh_result& row)
{
  row.input_min_angle = PMP::mesh_quality_report(input).min_angle;
  std::map<Mesh::Edge_index, bool> sharp;
  boost::associative_property_map<std::map<Mesh::Edge_index, bool> > ecm(sharp);
  PMP::detect_sharp_edges(input, cgal_sharp_angle, ecm);
  for(Mesh::Edge_index e : edges(input))
  {
    row.input_sharp_edges += get(ecm, e) ? 1 : 0;
    row.input_border_edges += is_border(e, input) ? 1 : 0;
  }
}

// Runs `remesh(copy)` on fresh copies of `input`, `repetitions` times; `remesh` returns the seconds
// it timed. Only the last output is kept, for the quality figures.
template <typename Remesh>
Method_result run_method(const std::string& mesh_name, const std::string& method_name, const Mesh& input,
                         std::size_t repetitions, Peak_memory& memory, const Remesh& remesh)
{
  Method_result result;
  result.done = true;
  std::optional<Mesh> last;
  for(std::size_t r = 0; r < repetitions; ++r)
  {
    Mesh copy = input;
    std::cerr << mesh_name << ": " << method_name << " run " << r + 1 << "/" << repetitions << " ..."
              << std::flush;
    const double baseline = start_peak_measurement(memory);
    const double seconds = remesh(copy);
    const double peak = peak_kb(memory);
    std::cerr << ' ' << std::fixed << std::setprecision(2) << seconds << " s, peak " << std::setprecision(1)
              << peak / 1024 << " MB\n"
              << std::defaultfloat;
    result.seconds.push_back(seconds);
    if(peak >= result.peak_kb)
    {
      result.peak_kb = peak;
      result.baseline_kb = baseline;
    }
    if(r + 1 == repetitions)
      last = std::move(copy);
  }
  result.median_seconds = median(result.seconds);

  std::cerr << mesh_name << ": " << method_name << " quality ..." << std::flush;
  const PMP::Mesh_quality_report quality = PMP::mesh_quality_report(*last);
  result.output_vertices = quality.number_of_vertices;
  result.mean_min_angle = quality.mean_min_angle;
  result.mean_max_angle = quality.mean_max_angle;
  result.min_angle = quality.min_angle;
  result.poor_percent = tools::poor_triangle_percentage(*last, tools::quality_poor_angle);
  result.hausdorff = PMP::relative_surface_distance(input, *last).hausdorff;
  std::cerr << " done\n";
  return result;
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double run_ours(Mesh& mesh)
{
  const auto start = std::chrono::steady_clock::now();
  PMP::graphcut_isotropic_remeshing(mesh);
  return seconds_since(start);
}

// CGAL's remeshing aiming at `target`, in the mesh's units.
double run_cgal_at(Mesh& mesh, double target)
{
  // The constrained edges are set up outside the timed part.
  auto ecm = mesh.add_property_map<Mesh::Edge_index, bool>("e:is_constrained", false).first;
  PMP::detect_sharp_edges(mesh, cgal_sharp_angle, ecm);
  const auto start = std::chrono::steady_clock::now();
  PMP::isotropic_remeshing(faces(mesh), target, mesh,
                           CGAL::parameters::number_of_iterations(cgal_iterations).edge_is_constrained_map(ecm));
  return seconds_since(start);
}

double run_cgal(Mesh& mesh)
{
  // The target length is computed outside the timed part.
  return run_cgal_at(mesh, tools::mean_edge_length(mesh));
}

// ---------------------------------------------------------------------------------------------
// Output

std::string fixed(double x, int digits)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << x;
  return s.str();
}

std::optional<double> linear_growth(const std::vector<Mesh_result>& results)
{
  const Mesh_result *small = nullptr, *large = nullptr;
  for(const auto& r : results)
  {
    if(r.name == "bear" && r.ours.done)
      small = &r;
    if(r.name == large_mesh_name && r.ours.done)
      large = &r;
  }
  if(small == nullptr || large == nullptr || small->ours.median_seconds <= 0)
    return std::nullopt;
  const double per_vertex_small = small->ours.median_seconds / double(small->input_vertices);
  const double per_vertex_large = large->ours.median_seconds / double(large->input_vertices);
  return per_vertex_large / per_vertex_small;
}

void write_table(std::ostream& out, const std::vector<Mesh_result>& results, const Peak_memory& memory,
                 const Machine& machine, std::size_t repetitions, std::size_t large_repetitions)
{
  const std::vector<std::pair<std::string, int>> columns = {
    {"mesh", 18},     {"vertices", 9},  {"ours s", 9},    {"CGAL s", 9},    {"ratio", 8},
    {"us/vert", 9},   {"ours MB", 9},   {"KB/vert", 9},   {"CGAL MB", 9},   {"MB ratio", 10},
    {"ours min", 10}, {"ours max", 10}, {"CGAL min", 10}, {"CGAL max", 10}, {"ours H", 9},
    {"CGAL H", 9}};
  auto cell = [&](std::size_t column, const std::string& text) {
    if(column == 0)
      out << std::left << std::setw(columns[column].second) << text << std::right;
    else
      out << std::setw(columns[column].second) << text;
  };
  for(std::size_t c = 0; c < columns.size(); ++c)
    cell(c, columns[c].first);
  out << '\n';
  const std::string none = "-";
  for(const auto& r : results)
  {
    const Method_result &o = r.ours, &g = r.cgal;
    const double n = double(r.input_vertices);
    cell(0, r.name);
    cell(1, std::to_string(r.input_vertices));
    cell(2, o.done ? fixed(o.median_seconds, 2) : none);
    cell(3, g.done ? fixed(g.median_seconds, 2) : none);
    cell(4, o.done && g.done && g.median_seconds > 0 ? fixed(o.median_seconds / g.median_seconds, 1) : none);
    cell(5, o.done ? fixed(1e6 * o.median_seconds / n, 0) : none);
    cell(6, o.done ? fixed(o.peak_kb / 1024, 1) : none);
    cell(7, o.done ? fixed(o.peak_kb / n, 2) : none);
    cell(8, g.done ? fixed(g.peak_kb / 1024, 1) : none);
    cell(9, o.done && g.done && g.peak_kb > 0 ? fixed(o.peak_kb / g.peak_kb, 2) : none);
    cell(10, o.done ? fixed(o.mean_min_angle, 2) : none);
    cell(11, o.done ? fixed(o.mean_max_angle, 2) : none);
    cell(12, g.done ? fixed(g.mean_min_angle, 2) : none);
    cell(13, g.done ? fixed(g.mean_max_angle, 2) : none);
    cell(14, o.done ? fixed(1e3 * o.hausdorff, 3) : none);
    cell(15, g.done ? fixed(1e3 * g.hausdorff, 3) : none);
    out << '\n';
  }
  const bool has_large = std::any_of(results.begin(), results.end(),
                                     [](const Mesh_result& r) { return r.name == large_mesh_name; });
  out << "\ntimes: median of " << repetitions << " run(s)";
  if(has_large)
    out << ", of " << large_repetitions << " on " << large_mesh_name;
  out << "; us/vert: our microseconds per input vertex;\n"
      << "ours MB, CGAL MB: peak resident memory (peak below); MB ratio: ours over CGAL's;\n"
      << "angles: mean min/max in degrees; "
      << "H: Hausdorff distance to the input, x1e-3 of its bounding-box diagonal;\npeak: "
      << (memory.per_run ? "resident memory high-water mark of the run (VmHWM after clear_refs)"
                         : "process peak resident memory (getrusage; /proc/self/clear_refs not writable)")
      << "\n";
  const std::optional<double> growth = linear_growth(results);
  if(has_large)
    out << "linear growth: our time per vertex on " << large_mesh_name << " / on bear = "
        << (growth ? fixed(*growth, 2) : std::string("n/a (needs ours on both meshes)")) << '\n';
  out << "machine: CPU " << machine.cpu << ", " << machine.hardware_threads << " hardware threads, "
      << machine.compiler << ", CGAL " << machine.cgal << ", CGAL_LINKED_WITH_TBB "
      << (machine.tbb ? "defined" : "not defined") << '\n';
}

std::string json_string(const std::string& s)
{
  std::string out = "\"";
  for(char c : s)
  {
    if(c == '"' || c == '\\')
      out += '\\';
    if(static_cast<unsigned char>(c) < 0x20)
      continue;
    out += c;
  }
  return out + "\"";
}

void write_json(std::ostream& out, const Method_result& m, std::size_t input_vertices)
{
  if(!m.done)
  {
    out << "null";
    return;
  }
  const double n = double(input_vertices);
  out << "{\"seconds\": " << tools::json_number(m.median_seconds) << ", \"runs\": [";
  for(std::size_t i = 0; i < m.seconds.size(); ++i)
    out << (i ? ", " : "") << tools::json_number(m.seconds[i]);
  out << "], \"microseconds_per_vertex\": " << tools::json_number(1e6 * m.median_seconds / n)
      << ", \"peak_mb\": " << tools::json_number(m.peak_kb / 1024)
      << ", \"peak_kb_per_vertex\": " << tools::json_number(m.peak_kb / n)
      << ", \"rss_before_mb\": " << tools::json_number(m.baseline_kb / 1024)
      << ", \"output_vertices\": " << m.output_vertices
      << ", \"mean_min_angle\": " << tools::json_number(m.mean_min_angle)
      << ", \"mean_max_angle\": " << tools::json_number(m.mean_max_angle)
      << ", \"min_angle\": " << tools::json_number(m.min_angle)
      << ", \"poor_percent\": " << tools::json_number(m.poor_percent)
      << ", \"hausdorff\": " << tools::json_number(m.hausdorff) << "}";
}

void write_json(std::ostream& out, const std::vector<Mesh_result>& results, const Peak_memory& memory,
                const Machine& machine)
{
  out << "{\"machine\": {\"cpu\": " << json_string(machine.cpu)
      << ", \"hardware_threads\": " << machine.hardware_threads
      << ", \"compiler\": " << json_string(machine.compiler) << ", \"cgal\": " << json_string(machine.cgal)
      << ", \"cgal_linked_with_tbb\": " << (machine.tbb ? "true" : "false") << "},\n"
      << " \"peak_memory\": " << json_string(memory.per_run ? "per_run" : "process_peak") << ",\n"
      << " \"meshes\": [";
  for(std::size_t i = 0; i < results.size(); ++i)
  {
    const Mesh_result& r = results[i];
    out << (i ? ",\n  " : "\n  ") << "{\"name\": " << json_string(r.name)
        << ", \"input_vertices\": " << r.input_vertices
        << ", \"input_min_angle\": " << tools::json_number(r.input_min_angle)
        << ", \"input_sharp_edges\": " << r.input_sharp_edges
        << ", \"input_border_edges\": " << r.input_border_edges << ", \"repetitions\": " << r.repetitions
        << ",\n   \"ours\": ";
    write_json(out, r.ours, r.input_vertices);
    out << ",\n   \"cgal\": ";
    write_json(out, r.cgal, r.input_vertices);
    out << "}";
  }
  const std::optional<double> growth = linear_growth(results);
  out << "],\n \"linear_growth\": " << (growth ? tools::json_number(*growth) : std::string("null")) << "}\n";
}

// ---------------------------------------------------------------------------------------------
// Command line

std::vector<std::string> split(const std::string& list)
{
  std::vector<std::string> items;
  std::stringstream in(list);
  std::string item;
  while(std::getline(in, item, ','))
  {
    if(!item.empty() && std::find(items.begin(), items.end(), item) == items.end())
      items.push_back(item);
  }
  return items;
}

// Seeds may be 0, unlike counts; anything but a whole number that fits an unsigned int is refused.
bool parse_seeds(const std::string& list, std::vector<unsigned int>& seeds)
{
  seeds.clear();
  for(const auto& item : split(list))
  {
    if(item.find_first_not_of("0123456789") != std::string::npos || item.size() > 10)
      return false;
    const unsigned long long value = std::stoull(item);
    if(value > (std::numeric_limits<unsigned int>::max)())
      return false;
    seeds.push_back(static_cast<unsigned int>(value));
  }
  return !seeds.empty();
}

// Positive finite numbers only: a factor of 0 would ask for edges of no length.
bool parse_factors(const std::string& list, std::vector<double>& factors)
{
  factors.clear();
  for(const auto& item : split(list))
  {
    double value = 0;
    if(!tools::parse_number(item, value) || !(value > 0))
      return false;
    factors.push_back(value);
  }
  return !factors.empty();
}

bool parse_count(const std::string& text, std::size_t& value)
{
  if(text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 9)
    return false;
  value = std::stoul(text);
  return value > 0;
}

[[noreturn]] void fail(const std::string& message)
{
  std::cerr << program << ": " << message << '\n';
  std::exit(EXIT_FAILURE);
}

// The figures as JSON into `file`, unless it is empty.
void write_json_file(const std::string& file, const std::vector<Mesh_result>& results, const Peak_memory& memory,
                     const Machine& machine)
{
  if(file.empty())
    return;
  std::ofstream out(file);
  write_json(out, results, memory, machine);
  if(!out)
    fail(file + ": cannot write");
}

// The --corpus mode's files: those of `data_dir` in a format the tools read, by name.
std::vector<std::string> corpus_files(const std::string& data_dir)
{
  std::vector<std::string> files;
  for(const auto& entry : std::filesystem::directory_iterator(data_dir))
  {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if(entry.is_regular_file() && (ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl"))
      files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The ratios of the median times, ours over CGAL's: their median, 90th percentile (nearest rank)
// and largest.
void write_ratio_summary(std::ostream& out, const std::vector<Mesh_result>& results)
{
  std::vector<std::pair<double, std::string>> ratios;
  for(const auto& r : results)
    if(r.ours.done && r.cgal.done && r.cgal.median_seconds > 0)
      ratios.emplace_back(r.ours.median_seconds / r.cgal.median_seconds, r.name);
  if(ratios.empty())
    return;
  std::sort(ratios.begin(), ratios.end());
  std::vector<double> values;
  for(const auto& r : ratios)
    values.push_back(r.first);
  const std::size_t rank = std::size_t(std::ceil(0.9 * double(values.size())));
  out << "time ratio, ours / CGAL, over " << values.size() << " meshes: median " << fixed(median(values), 1)
      << ", 90th percentile " << fixed(values[rank - 1], 1) << ", largest " << fixed(values.back(), 1) << " ("
      << ratios.back().second << ")\n";
}

// The --corpus mode: a row a mesh that reads and is small enough, then the ratios and the files
// left out.
int run_corpus_mode(const std::string& data_dir, std::size_t max_vertices, std::size_t repetitions,
                    const std::string& json_file)
{
  if(!std::filesystem::is_directory(data_dir))
    fail(data_dir + ": not a directory");
  const Machine machine = describe_machine();
  Peak_memory memory;
  std::vector<Mesh_result> results;
  std::vector<std::string> left_out;
  for(const auto& file : corpus_files(data_dir))
  {
    std::cerr << file << ": reading ..." << std::flush;
    Mesh_result row;
    row.name = file;
    row.repetitions = repetitions;
    try
    {
      const Mesh input = tools::read_mesh(data_dir + "/" + file, true);
      row.input_vertices = num_vertices(input);
      std::cerr << ' ' << row.input_vertices << " vertices\n";
      describe_input(input, row);
      if(row.input_vertices > max_vertices)
      {
        left_out.push_back(file + ": " + std::to_string(row.input_vertices) + " vertices");
        continue;
      }
      row.ours = run_method(file, "ours", input, repetitions, memory, run_ours);
      row.cgal = run_method(file, "cgal", input, repetitions, memory, run_cgal);
      results.push_back(std::move(row));
    }
    catch(const std::exception& e)
    {
      std::cerr << '\n';
      const std::string what = e.what();
      left_out.push_back(what.rfind(data_dir, 0) == 0 ? what.substr(data_dir.size() + 1) : file + ": " + what);
    }
  }
  write_table(std::cout, results, memory, machine, repetitions, 0);
  write_ratio_summary(std::cout, results);
  std::cout << left_out.size() << " files left out (over " << max_vertices << " vertices, or refused):\n";
  for(const auto& l : left_out)
    std::cout << "  " << l << '\n';
  write_json_file(json_file, results, memory, machine);
  return EXIT_SUCCESS;
}

// The --quality mode. The table goes out even when a mesh fails, with the rows done before it, so
// that a long run is not lost to its last mesh; the exit status then says it failed.
int run_quality_mode(const tools::Quality_options& options, const std::string& json_file)
{
  // Refuse a missing file before spending minutes on the meshes that precede it.
  for(const auto& m : options.meshes)
  {
    const std::string path = options.data_dir + "/" + m + ".off";
    if(!std::ifstream(path))
      fail(path + ": cannot open file");
  }
  std::vector<tools::Quality_row> rows;
  std::string error;
  try
  {
    tools::run_quality_comparison(options, run_cgal_at, rows);
  }
  catch(const tools::Input_error& e)
  {
    error = e.what();
  }
  catch(const std::exception& e)
  {
    error = std::string("error: ") + e.what();
  }
  if(!error.empty())
    std::cerr << '\n';
  tools::write_quality_table(std::cout, rows);
  const bool resamples = options.resampling || !options.length_factors.empty();
  const auto bounds = options.sharp_angle_bounds.value_or(
    PMP::internal::Graphcut_remeshing::Remeshing_options().default_sharp_angle_bounds(
      options.resampling, !options.length_factors.empty()));
  std::cout << "ours: " << (resamples ? "re-sampling" : "the paper's connectivity (--no-resampling)")
            << ", sharp-angle bounds " << bounds.first << " " << bounds.second << '\n';
  if(!json_file.empty())
  {
    std::ofstream out(json_file);
    tools::write_quality_json(out, rows);
    if(!out)
      fail(json_file + ": cannot write");
  }
  if(!error.empty())
    fail(error);
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  std::string data_dir = GRAPHCUT_REMESHING_DATA_DIR;
  std::size_t repetitions = 3, large_repetitions = 1;
  std::vector<std::string> meshes = all_meshes;
  bool skip_large = false, run_ours_method = true, run_cgal_method = true;
  std::string json_file;
  // The two modes take different mesh names, so --meshes is checked once the mode is known.
  bool quality = false, no_resampling = false, corpus = false, repetitions_given = false,
       max_vertices_given = false;
  std::size_t max_vertices = corpus_max_vertices;
  std::optional<std::pair<double, double>> sharp_angle_bounds;
  std::optional<std::string> mesh_list, seed_list, length_factor_list;
  std::vector<std::string> timing_only; // options of the timing mode given, refused with --quality
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        fail(arg + " needs a value (see --help)");
      return argv[++i];
    };
    if(arg == "--help" || arg == "-h")
    {
      std::cout << usage();
      return EXIT_SUCCESS;
    }
    else if(arg == "--data")
      data_dir = value();
    else if(arg == "--quality")
      quality = true;
    else if(arg == "--corpus")
      corpus = true;
    else if(arg == "--max-vertices")
    {
      max_vertices_given = true;
      if(!parse_count(value(), max_vertices))
        fail(arg + " needs a positive whole number");
    }
    else if(arg == "--seeds")
      seed_list = value();
    else if(arg == "--no-resampling")
      no_resampling = true;
    else if(arg == "--length-factors")
      length_factor_list = value();
    else if(arg == "--sharp-angle")
    {
      const std::string low = value(), high = value();
      std::pair<double, double> bounds;
      if(!tools::parse_number(low, bounds.first) || !tools::parse_number(high, bounds.second) || !(bounds.first <= bounds.second) ||
         bounds.second > 180)
        fail("--sharp-angle needs LOW <= HIGH <= 180");
      sharp_angle_bounds = bounds;
    }
    else if(arg == "--repetitions" || arg == "--large-repetitions")
    {
      timing_only.push_back(arg);
      std::size_t& target = arg == "--repetitions" ? repetitions : large_repetitions;
      repetitions_given = repetitions_given || arg == "--repetitions";
      if(!parse_count(value(), target))
        fail(arg + " needs a positive whole number");
    }
    else if(arg == "--meshes")
      mesh_list = value();
    else if(arg == "--methods")
    {
      timing_only.push_back(arg);
      const std::vector<std::string> methods = split(value());
      run_ours_method = run_cgal_method = false;
      for(const auto& m : methods)
      {
        if(m == "ours")
          run_ours_method = true;
        else if(m == "cgal")
          run_cgal_method = true;
        else
          fail("unknown method " + m + " (expected ours or cgal)");
      }
      if(methods.empty())
        fail("--methods needs at least one method name");
    }
    else if(arg == "--skip-large")
    {
      timing_only.push_back(arg);
      skip_large = true;
    }
    else if(arg == "--json")
      json_file = value();
    else
    {
      std::cerr << program << ": unknown argument " << arg << "\n" << usage();
      return EXIT_FAILURE;
    }
  }
  if(mesh_list && split(*mesh_list).empty())
    fail("--meshes needs at least one mesh name");
  if(corpus)
  {
    if(quality || mesh_list || !run_ours_method || !run_cgal_method || skip_large || seed_list || no_resampling ||
       sharp_angle_bounds || length_factor_list)
      fail("--corpus takes only --max-vertices, --repetitions, --data and --json");
    return run_corpus_mode(data_dir, max_vertices, repetitions_given ? repetitions : 1, json_file);
  }
  if(max_vertices_given)
    fail("--max-vertices applies to --corpus only");
  if(quality)
  {
    if(!timing_only.empty())
      fail(timing_only.front() + " does not apply to --quality");
    tools::Quality_options options;
    options.data_dir = data_dir;
    if(mesh_list)
      options.meshes = split(*mesh_list);
    if(seed_list && !parse_seeds(*seed_list, options.seeds))
      fail("--seeds needs a comma-separated list of whole numbers below 2^32");
    options.resampling = !no_resampling;
    options.sharp_angle_bounds = sharp_angle_bounds;
    if(length_factor_list && !parse_factors(*length_factor_list, options.length_factors))
      fail("--length-factors needs a comma-separated list of positive numbers");
    return run_quality_mode(options, json_file);
  }
  if(seed_list || no_resampling || sharp_angle_bounds || length_factor_list)
    fail(std::string(seed_list             ? "--seeds"
                     : no_resampling       ? "--no-resampling"
                     : sharp_angle_bounds  ? "--sharp-angle"
                                           : "--length-factors") +
         " applies to --quality only");
  if(mesh_list)
  {
    meshes = split(*mesh_list);
    for(const auto& m : meshes)
      if(std::find(all_meshes.begin(), all_meshes.end(), m) == all_meshes.end())
        fail("unknown mesh " + m + " (expected fandisk, cow, triceratops, bear or " + large_mesh_name + ")");
  }
  if(skip_large)
    meshes.erase(std::remove(meshes.begin(), meshes.end(), large_mesh_name), meshes.end());
  if(meshes.empty())
    fail("no mesh left to run");

  // Refuse a missing file before spending minutes on the meshes that precede it.
  for(const auto& m : meshes)
  {
    const std::string path = data_dir + "/" + (m == large_mesh_name ? std::string("bear") : m) + ".off";
    if(!std::ifstream(path))
      fail(path + ": cannot open file");
  }

  const Machine machine = describe_machine();
  Peak_memory memory;
  std::vector<Mesh_result> results;
  try
  {
    for(const auto& name : meshes)
    {
      Mesh_result row;
      row.name = name;
      const bool large = name == large_mesh_name;
      row.repetitions = large ? large_repetitions : repetitions;
      // The input lives in this scope only, so the large mesh never shares the process with
      // another input.
      std::cerr << name << ": " << (large ? "building from bear.off (Loop x2, jitter)" : "reading") << " ..."
                << std::flush;
      const Mesh input = large ? build_large_mesh(data_dir) : tools::read_mesh(data_dir + "/" + name + ".off", true);
      row.input_vertices = num_vertices(input);
      std::cerr << ' ' << row.input_vertices << " vertices\n";
      describe_input(input, row);
      if(run_ours_method)
        row.ours = run_method(name, "ours", input, row.repetitions, memory, run_ours);
      if(run_cgal_method)
        row.cgal = run_method(name, "cgal", input, row.repetitions, memory, run_cgal);
      results.push_back(std::move(row));
    }
  }
  catch(const tools::Input_error& e)
  {
    std::cerr << '\n';
    fail(e.what());
  }
  catch(const std::exception& e)
  {
    std::cerr << '\n';
    fail(std::string("error: ") + e.what());
  }

  write_table(std::cout, results, memory, machine, repetitions, large_repetitions);
  write_json_file(json_file, results, memory, machine);
  return EXIT_SUCCESS;
}
