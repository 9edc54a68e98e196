// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// graphcut_remesh INPUT OUTPUT [options]: remeshes INPUT, writes OUTPUT, prints the before/after
// quality table and the time.

#include "tool_support.h"

#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#ifdef _WIN32
#include <io.h>
#else
#include <unistd.h>
#endif

namespace PMP = CGAL::Polygon_mesh_processing;
namespace GP = PMP::graphcut_parameters;
namespace tools = graphcut_remeshing_tools;

namespace {

namespace GR = PMP::internal::Graphcut_remeshing;

// --target-vertices: how close to N the count must land, and how many runs may get it there.
constexpr double vertex_count_tolerance = 0.05;
constexpr int max_vertex_count_runs = 4;

// The edge length of equilateral triangles that cover `area` with about `vertices` vertices (a
// closed triangle mesh has about twice as many triangles as vertices).
double length_for_vertices(double area, std::size_t vertices)
{
  return std::sqrt(2 * area / (std::sqrt(3.0) * double(vertices)));
}

// The help, with the library's defaults (the options not given are left to the library).
std::string usage()
{
  const GR::Remeshing_options defaults;
  std::ostringstream out;
  out << "usage: graphcut_remesh INPUT OUTPUT [options]\n"
         "\n"
         "Remeshes the triangle mesh INPUT into nearly equilateral triangles that stay close to the input\n"
         "surface, writes OUTPUT and prints the quality before and after. Both files are OFF, OBJ, PLY or\n"
         "STL, by their extension; PLY and STL are written in binary. On a terminal, a progress bar is\n"
         "shown on stderr.\n"
         "\n"
      << "  --iterations N          non-greedy relocation iterations (default " << defaults.number_of_iterations
      << ";\n                          with --no-resampling, --target-length or --target-vertices, the paper's "
      << defaults.paper_iterations.first << ")\n"
      << "  --greedy-iterations N   final greedy iterations (default " << defaults.number_of_greedy_iterations
      << "; with\n                          --no-resampling, --target-length or --target-vertices "
      << defaults.paper_iterations.second << ")\n"
      << "  --lambda-data X         weight of the data term, unit-box scale (default " << defaults.weights.lambda_data
      << ")\n"
      << "  --face-data-weight X    weight of the data term at triangle centroids, relative to\n"
      << "                          lambda-data (default " << defaults.weights.face_data_weight << ")\n"
      << "  --seed N                random seed; same input and seed, same output (default " << defaults.random_seed
      << ")\n"
         "  --no-connectivity       relocate vertices only, never change the connectivity (default:\n"
         "                          the connectivity is optimised)\n"
      << "  --sharp-angle LOW HIGH  the dihedral angles (degrees) of the sharp-edge hysteresis (default "
      << defaults.sharp_angle_bounds.first << " " << defaults.sharp_angle_bounds.second << ";\n"
      << "                          with --no-resampling, --target-length or --target-vertices, the\n"
      << "                          paper's " << defaults.paper_sharp_angle_bounds.first << " "
      << defaults.paper_sharp_angle_bounds.second << ")\n"
      << "  --target-length L       re-sample the surface to edges of about L (the input's units),\n"
      << "                          shorter where it is curved (default: the input's mean edge length,\n"
      << "                          re-sampled)\n"
      << "  --target-vertices N     re-sample the surface to about N vertices: the target length is\n"
      << "                          found from the surface's area, then corrected by the count a run\n"
      << "                          gives, until it lands within " << int(100 * vertex_count_tolerance)
      << " % of N (at most " << max_vertex_count_runs << " runs, the\n"
      << "                          closest kept; default: none)\n"
      << "  --sizing-tolerance E    how far (input units) the triangles may leave the surface: re-sampling\n"
      << "                          then aims at the lengths whose triangles keep within E, between a\n"
      << "                          quarter of the target length and the target length; without\n"
      << "                          re-sampling, E shortens the edges aimed at where it is curved\n"
      << "                          (default: none, a field for the target length's count)\n"
      << "  --distance-bound D      keep the output within D (input units) of the input, both ways:\n"
      << "                          every operation is checked before it is taken, the sizing field\n"
      << "                          is that of a tolerance of D unless --sizing-tolerance is given;\n"
      << "                          the distance achieved is measured and printed (default: none)\n"
      << "  --distance-bound-ratio R  the same, D = R times the input's bounding-box diagonal\n"
      << "                          (default: none)\n"
      << "  --no-resampling         the paper's own connectivity passes (flips, splits and collapses\n"
      << "                          in flat regions, vertex splits) instead of re-sampling the surface\n"
      << "                          to a curvature-adapted sizing field (default: "
      << (defaults.resampling ? "re-sampling" : "the paper's") << ")\n"
      << "  --threads N             run the remesher's parallel loops on at most N threads; the output\n"
      << "                          does not depend on N (default: all cores"
#ifndef CGAL_LINKED_WITH_TBB
      << "; this build has no TBB and runs on one"
#endif
      << ")\n"
         "  --quiet                 print nothing but errors, no progress bar (default: off)\n"
         "  --json FILE             write the quality figures, distances, time and energies as JSON\n"
         "                          (default: no JSON)\n"
         "  --help                  print this help and exit (default: off)\n";
  return out.str();
}

// The formats write_polygon_mesh() writes, by extension (it also lowers the case).
bool is_writable_mesh_file(const std::string& path)
{
  const std::string::size_type dot = path.rfind('.');
  if(dot == std::string::npos)
    return false;
  std::string ext = path.substr(dot + 1);
  for(char& c : ext)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == "off" || ext == "obj" || ext == "ply" || ext == "stl";
}

bool stderr_is_terminal()
{
#ifdef _WIN32
  return _isatty(_fileno(stderr)) != 0;
#else
  return isatty(STDERR_FILENO) != 0;
#endif
}

// One line on a terminal, redrawn after each iteration: phase, iteration over both phases, energy
// and the time left at the pace so far. Only for a person watching: never written to a pipe or a
// file, where it would be noise in a log.
class Progress_bar
{
public:
  Progress_bar(std::size_t relocation_iterations, std::size_t greedy_iterations)
    : m_relocation(relocation_iterations), m_total(relocation_iterations + greedy_iterations),
      m_start(std::chrono::steady_clock::now())
  {
    draw("preparing", 0, std::string());
  }

  ~Progress_bar() { clear(); }

  bool operator()(const PMP::Graphcut_remeshing_progress& p)
  {
    const bool greedy = p.phase == PMP::Graphcut_remeshing_progress::GREEDY_FITTING;
    const std::size_t done = (greedy ? m_relocation : 0) + p.iteration;
    char energy[48];
    std::snprintf(energy, sizeof(energy), "energy %.6g", p.energy);
    draw(greedy ? "greedy fitting" : "relocation", done, energy);
    return true;
  }

  // Rubs the line out, so that what follows starts on a clean line.
  void clear()
  {
    if(m_drawn)
      std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
    m_drawn = false;
  }

private:
  void draw(const char* phase, std::size_t done, const std::string& energy)
  {
    const int width = 24;
    const std::size_t total = (std::max)(m_total, std::size_t(1));
    const int filled = int(double(width) * double((std::min)(done, total)) / double(total));
    std::string bar(std::size_t(filled), '#');
    bar.resize(std::size_t(width), '.');
    std::string eta = "ETA --:--";
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    if(done > 0 && done <= total)
    {
      const long left = std::lround(elapsed / double(done) * double(total - done));
      char text[32];
      std::snprintf(text, sizeof(text), "ETA %ld:%02ld", left / 60, left % 60);
      eta = text;
    }
    // \033[K clears what a longer previous line left on the right.
    std::fprintf(stderr, "\r%-14s [%s] %zu/%zu  %s%s%s\033[K", phase, bar.c_str(), done, m_total, energy.c_str(),
                 energy.empty() ? "" : "  ", eta.c_str());
    std::fflush(stderr);
    m_drawn = true;
  }

  std::size_t m_relocation, m_total;
  std::chrono::steady_clock::time_point m_start;
  bool m_drawn = false;
};

} // namespace

int main(int argc, char** argv)
{
  // What the user gives; the rest is left to the library's defaults.
  std::optional<std::size_t> iterations, greedy_iterations;
  std::optional<double> lambda_data, face_data_weight, target_length, sizing_tolerance;
  std::optional<double> distance_bound, distance_bound_ratio;
  std::optional<std::size_t> target_vertices, threads;
  std::optional<unsigned int> seed;
  bool quiet = false, connectivity = true;
  bool resampling = GR::Remeshing_options().resampling;
  std::optional<double> sharp_low, sharp_high;
  std::string json_file;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](auto& target) {
      typename std::remove_reference_t<decltype(target)>::value_type number{};
      if(i + 1 >= argc || !tools::parse_number(argv[i + 1], number))
      {
        std::cerr << "graphcut_remesh: " << arg << " needs a non-negative number\n";
        std::exit(EXIT_FAILURE);
      }
      target = number;
      ++i;
    };
    if(arg == "--help" || arg == "-h")
    {
      std::cout << usage();
      return EXIT_SUCCESS;
    }
    else if(arg == "--iterations") value(iterations);
    else if(arg == "--greedy-iterations") value(greedy_iterations);
    else if(arg == "--lambda-data") value(lambda_data);
    else if(arg == "--face-data-weight") value(face_data_weight);
    else if(arg == "--seed") value(seed);
    else if(arg == "--no-connectivity") connectivity = false;
    else if(arg == "--no-resampling") resampling = false;
    else if(arg == "--target-length")
    {
      value(target_length);
      if(!(*target_length > 0))
      {
        std::cerr << "graphcut_remesh: --target-length needs a positive length\n";
        return EXIT_FAILURE;
      }
    }
    else if(arg == "--sizing-tolerance")
    {
      value(sizing_tolerance);
      if(!(*sizing_tolerance > 0))
      {
        std::cerr << "graphcut_remesh: --sizing-tolerance needs a positive length\n";
        return EXIT_FAILURE;
      }
    }
    else if(arg == "--distance-bound" || arg == "--distance-bound-ratio")
    {
      std::optional<double>& bound = arg == "--distance-bound" ? distance_bound : distance_bound_ratio;
      value(bound);
      if(!(*bound > 0))
      {
        std::cerr << "graphcut_remesh: " << arg << " needs a positive number\n";
        return EXIT_FAILURE;
      }
    }
    else if(arg == "--target-vertices" || arg == "--threads")
    {
      std::optional<std::size_t>& count = arg == "--threads" ? threads : target_vertices;
      value(count);
      if(!(*count > 0))
      {
        std::cerr << "graphcut_remesh: " << arg << " needs a positive number\n";
        return EXIT_FAILURE;
      }
    }
    else if(arg == "--sharp-angle")
    {
      value(sharp_low);
      value(sharp_high);
      if(!(*sharp_low <= *sharp_high) || *sharp_high > 180)
      {
        std::cerr << "graphcut_remesh: --sharp-angle needs LOW <= HIGH <= 180\n";
        return EXIT_FAILURE;
      }
    }
    else if(arg == "--quiet") quiet = true;
    else if(arg == "--json")
    {
      if(i + 1 >= argc)
      {
        std::cerr << "graphcut_remesh: --json needs a file name\n";
        return EXIT_FAILURE;
      }
      json_file = argv[++i];
    }
    else if(arg.size() > 1 && arg[0] == '-')
    {
      std::cerr << "graphcut_remesh: unknown option " << arg << " (see --help)\n";
      return EXIT_FAILURE;
    }
    else
      files.push_back(arg);
  }
  if(distance_bound && distance_bound_ratio)
  {
    std::cerr << "graphcut_remesh: give --distance-bound or --distance-bound-ratio, not both\n";
    return EXIT_FAILURE;
  }
  if(target_length && target_vertices)
  {
    std::cerr << "graphcut_remesh: give --target-length or --target-vertices, not both\n";
    return EXIT_FAILURE;
  }
#ifdef CGAL_LINKED_WITH_TBB
  std::optional<tbb::global_control> thread_limit;
  if(threads)
    thread_limit.emplace(tbb::global_control::max_allowed_parallelism, *threads);
#endif
  if(files.size() != 2)
  {
    std::cerr << "graphcut_remesh: expected INPUT and OUTPUT (see --help)\n" << usage();
    return EXIT_FAILURE;
  }
  // Before the work, not after: a remeshing can take minutes.
  if(!is_writable_mesh_file(files[1]))
  {
    std::cerr << "graphcut_remesh: " << files[1] << ": cannot write this format (OFF, OBJ, PLY or STL expected)\n";
    return EXIT_FAILURE;
  }

  try
  {
    std::vector<std::string> notices;
    const tools::Mesh input = tools::read_mesh(files[0], true, &notices);
    if(!quiet)
      for(const std::string& n : notices)
        std::cerr << "graphcut_remesh: " << n << '\n';
    tools::Mesh mesh = input;

    const auto start = std::chrono::steady_clock::now();
    // The named parameters hold a value for every option: the user's, or the library's default.
    const GR::Remeshing_options defaults;
    if(distance_bound_ratio)
      distance_bound = *distance_bound_ratio * PMP::internal::Graphcut_remeshing::bounding_box_diagonal(input, get(CGAL::vertex_point, input));
    // A density asked for re-samples, whatever --no-resampling says.
    const bool resamples = resampling || target_length || target_vertices;
    const std::pair<double, double> default_bounds =
      defaults.default_sharp_angle_bounds(resamples, target_length || target_vertices);
    const std::pair<std::size_t, std::size_t> default_iterations = defaults.default_iterations(resamples, target_length || target_vertices);
    const std::size_t relocation_iterations = iterations.value_or(default_iterations.first),
                      greedy = greedy_iterations.value_or(default_iterations.second);
    const auto parameters = GP::combine(
      CGAL::parameters::number_of_iterations(relocation_iterations).random_seed(seed.value_or(defaults.random_seed)),
      GP::number_of_greedy_iterations(greedy),
      GP::lambda_data(lambda_data.value_or(defaults.weights.lambda_data)),
      GP::face_data_weight(face_data_weight.value_or(defaults.weights.face_data_weight)),
      GP::do_connectivity_optimization(connectivity), GP::resampling(resampling),
      GP::distance_bound(distance_bound.value_or(0)),
      GP::sharp_angle_bounds(std::make_pair(sharp_low.value_or(default_bounds.first),
                                            sharp_high.value_or(default_bounds.second))));
    // The call with a target length, as isotropic_remeshing's, or the one without.
    auto remesh_with = [&](const auto& np) {
      mesh = input;
      return target_length ? PMP::graphcut_isotropic_remeshing(faces(mesh), *target_length, mesh, np)
                           : PMP::graphcut_isotropic_remeshing(mesh, np);
    };
    auto remesh = [&](const auto& np) {
      return sizing_tolerance ? remesh_with(GP::combine(np, GP::sizing_tolerance(*sizing_tolerance))) : remesh_with(np);
    };
    auto run = [&] {
      if(quiet || !stderr_is_terminal())
        return remesh(parameters);
      Progress_bar bar(relocation_iterations, greedy);
      // The visitor is copied: it refers to the bar, which clears its line when it goes.
      return remesh(GP::combine(parameters, GP::visitor([&bar](const PMP::Graphcut_remeshing_progress& p) { return bar(p); })));
    };
    PMP::Graphcut_remeshing_statistics stats;
    int runs = 0, kept_run = 1;
    if(target_vertices)
    {
      // The count falls as a power of the length: the square at first, then the power the last
      // two runs show (coarse targets, where feature lines hold vertices, fall slower; a count
      // that did not fall keeps the power as it was). The run closest to N is kept.
      target_length = length_for_vertices(PMP::area(input), *target_vertices);
      double power = 2, previous_length = 0, previous_count = 0;
      tools::Mesh closest;
      PMP::Graphcut_remeshing_statistics closest_stats;
      double closest_error = std::numeric_limits<double>::infinity(), closest_length = *target_length;
      for(;;)
      {
        stats = run();
        const double count = double(mesh.number_of_vertices()), ratio = count / double(*target_vertices);
        ++runs;
        if(std::abs(ratio - 1) < closest_error)
        {
          closest_error = std::abs(ratio - 1);
          closest = mesh;
          closest_stats = stats;
          closest_length = *target_length;
          kept_run = runs;
        }
        if(runs == max_vertex_count_runs || std::abs(ratio - 1) <= vertex_count_tolerance)
          break;
        if(!quiet)
          std::cerr << "graphcut_remesh: " << mesh.number_of_vertices() << " vertices at length " << *target_length
                    << ", again\n";
        if(previous_count > 0)
        {
          const double measured = -std::log(count / previous_count) / std::log(*target_length / previous_length);
          if(std::isfinite(measured) && measured > 0)
            power = std::clamp(measured, 0.5, 4.0);
        }
        previous_length = *target_length;
        previous_count = count;
        *target_length *= std::pow(ratio, 1 / power);
      }
      mesh = std::move(closest);
      stats = closest_stats;
      target_length = closest_length;
    }
    else
    {
      stats = run();
      runs = 1;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    if(!CGAL::IO::write_polygon_mesh(files[1], mesh, CGAL::parameters::stream_precision(17)))
      throw tools::Input_error(files[1] + ": cannot write the output mesh");
    if(quiet && json_file.empty())
      return EXIT_SUCCESS; // the figures below are for the table and the JSON only (the distances are not cheap)

    // The connectivity the run used, and the length it aimed at: the one asked for or found, else
    // the input's mean.
    const std::string mode = !connectivity ? "relocation only" : resamples ? "re-sampling" : "paper";
    const double target_edge_length = target_length ? *target_length : tools::mean_edge_length(input);
    const PMP::Mesh_quality_report before = PMP::mesh_quality_report(input);
    const PMP::Mesh_quality_report after = PMP::mesh_quality_report(mesh);
    const PMP::Relative_surface_distance distance = PMP::relative_surface_distance(input, mesh);
    std::vector<std::pair<std::string, std::string> > rows{{"mode", mode},
                                                           {"target edge length", tools::json_number(target_edge_length)}};
    if(distance_bound)
    {
      rows.emplace_back("distance bound", tools::json_number(*distance_bound));
      rows.emplace_back("distance achieved", tools::json_number(stats.hausdorff_distance));
    }
    if(!quiet)
    {
      tools::write_table(std::cout, {"input", "output"}, {before, after}, &distance, nullptr, rows);
      std::cout << "time (s)                  " << std::setw(32) << seconds << '\n';
    }
    if(!json_file.empty())
    {
      std::ofstream out(json_file);
      out << "{\"input\": ";
      tools::write_json(out, before);
      out << ", \"output\": ";
      tools::write_json(out, after);
      out << ", \"distance\": ";
      tools::write_json(out, distance);
      out << ", \"seconds\": " << tools::json_number(seconds);
      out << ", \"mode\": \"" << mode << "\", \"target_edge_length\": " << tools::json_number(target_edge_length);
      if(distance_bound)
        out << ", \"distance_bound\": " << tools::json_number(*distance_bound)
            << ", \"distance_achieved\": " << tools::json_number(stats.hausdorff_distance);
      if(target_vertices)
        out << ", \"target_vertices\": " << *target_vertices << ", \"runs\": " << runs << ", \"kept_run\": " << kept_run;
      out << ", \"energy\": [";
      for(std::size_t i = 0; i < stats.energies.size(); ++i)
        out << (i ? ", " : "") << std::setprecision(17) << stats.energies[i];
      out << "], \"connectivity_passes\": [";
      for(std::size_t i = 0; i < stats.connectivity_passes.size(); ++i)
        out << (i ? ", " : "") << stats.connectivity_passes[i];
      out << "], \"iterations\": " << stats.number_of_iterations << ", \"moves\": " << stats.number_of_moves
          << ", \"flips\": " << stats.number_of_flips << ", \"splits\": " << stats.number_of_splits
          << ", \"collapses\": " << stats.number_of_collapses
          << ", \"vertex_splits\": " << stats.number_of_vertex_splits
          << ", \"undone_passes\": " << stats.number_of_undone_passes << "}\n";
      if(!out)
        throw tools::Input_error(json_file + ": cannot write");
    }
  }
  catch(const tools::Input_error& e)
  {
    std::cerr << "graphcut_remesh: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  catch(const PMP::Graphcut_remeshing_input_error& e)
  {
    std::cerr << "graphcut_remesh: " << files[0] << ": " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  catch(const std::exception& e)
  {
    std::cerr << "graphcut_remesh: error: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
