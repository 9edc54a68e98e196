// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// render_mesh: SVG pictures of triangle meshes made with nothing but CGAL, for the manual and the
// README (doc/Graphcut_remeshing/fig/make_figures.sh).
//
//   render_mesh [options] MESH OUTPUT.svg
//     the mesh seen from a direction, flat-shaded, each triangle coloured by its smallest angle
//   render_mesh --histogram [options] MESH [MESH ...] OUTPUT.svg
//     the distribution of the triangles' smallest angles (or of all their angles), one curve a mesh

#include "tool_support.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace tools = graphcut_remeshing_tools;

namespace {

using Vector = tools::Kernel::Vector_3;

const char* const usage =
  "usage: render_mesh [options] MESH OUTPUT.svg\n"
  "       render_mesh --histogram [options] MESH [MESH ...] OUTPUT.svg\n"
  "\n"
  "Draws the triangle mesh MESH (OFF, OBJ, PLY or STL) as an SVG picture: an orthographic view,\n"
  "flat-shaded, each triangle coloured by its smallest angle, with a colour bar. With --histogram,\n"
  "draws instead the distribution of the triangles' smallest angles of one or more meshes (e.g.\n"
  "before and after remeshing), as shares of their triangles.\n"
  "\n"
  "Picture options:\n"
  "  --view X Y Z      direction from the mesh towards the viewer (default 1 1 2)\n"
  "  --up X Y Z        direction that points up in the picture (default 0 1 0)\n"
  "  --no-edges        do not draw the triangles' edges (default: drawn)\n"
  "Histogram options:\n"
  "  --all-angles      the distribution of all three angles of each triangle (default: the\n"
  "                    smallest angle only)\n"
  "  --bin DEGREES     width of a bin (default 1, or 2 with --all-angles)\n"
  "  --label TEXT      name of a mesh in the legend, once per mesh in order (default: file name)\n"
  "Both:\n"
  "  --size W          width of the picture in pixels (default 800 for a picture, 640 for a\n"
  "                    histogram)\n"
  "  --title TEXT      title at the top (default: the file name, or \"Angles of the triangles\")\n"
  "  --help            print this help\n";

struct Rgb
{
  double r, g, b;
};

struct Colour_stop
{
  double angle;
  Rgb colour;
};

// The colour scale of the smallest angle, from slivers (dark red) to the equilateral 60 degrees
// (blue-green), through orange and a pale yellow around 40 degrees, where remeshing moves most
// triangles. Piecewise linear between the stops, so that an SVG gradient with the same stops draws
// the colour bar exactly.
const Colour_stop angle_scale[] = {
  {0, {0.45, 0.02, 0.12}}, {15, {0.82, 0.20, 0.16}}, {30, {0.96, 0.58, 0.24}},
  {40, {0.98, 0.88, 0.52}}, {50, {0.58, 0.80, 0.47}}, {60, {0.13, 0.54, 0.50}}};
const double max_scale_angle = 60;

Rgb angle_colour(double degrees)
{
  const std::size_t n = sizeof(angle_scale) / sizeof(angle_scale[0]);
  if(!(degrees > angle_scale[0].angle))
    return angle_scale[0].colour;
  for(std::size_t i = 1; i < n; ++i)
    if(degrees <= angle_scale[i].angle)
    {
      const Colour_stop& a = angle_scale[i - 1];
      const Colour_stop& b = angle_scale[i];
      const double t = (degrees - a.angle) / (b.angle - a.angle);
      return {a.colour.r + t * (b.colour.r - a.colour.r), a.colour.g + t * (b.colour.g - a.colour.g),
              a.colour.b + t * (b.colour.b - a.colour.b)};
    }
  return angle_scale[n - 1].colour;
}

std::string hex(const Rgb& c)
{
  auto byte = [](double x) { return int(std::lround(255 * std::clamp(x, 0.0, 1.0))); };
  char text[8];
  std::snprintf(text, sizeof(text), "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return text;
}

// A coordinate with one decimal, the shortest way: a tenth of a pixel is finer than any screen,
// and it keeps a picture of 13k triangles well under a megabyte.
std::string coordinate(double x)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f", x);
  std::string s = text;
  if(s.size() > 2 && s.compare(s.size() - 2, 2, ".0") == 0)
    s.resize(s.size() - 2);
  return s == "-0" ? "0" : s;
}

std::string fixed(double x, int digits)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << x;
  return s.str();
}

std::string escape_xml(const std::string& text)
{
  std::string out;
  for(char c : text)
  {
    switch(c)
    {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string base_name(const std::string& path)
{
  const std::string::size_type slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

double length(const Vector& v) { return std::sqrt(v.squared_length()); }

// The three angles of a triangle, in degrees; atan2 keeps thin triangles accurate.
std::array<double, 3> triangle_angles(const tools::Mesh& mesh, tools::Mesh::Face_index f)
{
  const auto h = mesh.halfedge(f);
  const tools::Kernel::Point_3 p[3] = {mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                       mesh.point(mesh.target(mesh.next(h)))};
  std::array<double, 3> angles;
  for(int i = 0; i < 3; ++i)
  {
    const Vector u = p[(i + 1) % 3] - p[i], v = p[(i + 2) % 3] - p[i];
    angles[i] = std::atan2(length(CGAL::cross_product(u, v)), u * v) * 180.0 / CGAL_PI;
  }
  return angles;
}

// The opening of an SVG file: size, a comment that says how it was made, white background, a
// title and a line of figures.
void write_header(std::ostream& out, double width, double height, const std::string& title,
                  const std::string& subtitle, const std::string& comment)
{
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << coordinate(width) << "\" height=\""
      << coordinate(height) << "\" viewBox=\"0 0 " << coordinate(width) << ' ' << coordinate(height)
      << "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n"
      << "<!-- " << [&] {
           // "--" may not appear in an XML comment.
           std::string text = escape_xml(comment);
           for(std::string::size_type k = text.find("--"); k != std::string::npos; k = text.find("--", k))
             text.replace(k, 2, "- -");
           return text;
         }() << " -->\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
      << "<text x=\"12\" y=\"24\" font-size=\"16\" font-weight=\"bold\" fill=\"#222222\">" << escape_xml(title)
      << "</text>\n"
      << "<text x=\"12\" y=\"42\" font-size=\"12\" fill=\"#555555\">" << escape_xml(subtitle) << "</text>\n";
}

// ---------------------------------------------------------------------------------------------
// The picture

struct Picture_options
{
  Vector view = Vector(1, 1, 2);
  Vector up = Vector(0, 1, 0);
  double width = 800;
  bool edges = true;
  std::string title;
};

void write_picture(std::ostream& out, const tools::Mesh& mesh, const std::string& file, const Picture_options& options)
{
  using Mesh = tools::Mesh;

  // The camera frame: `toward` points from the mesh to the viewer; `right` and `up` span the
  // picture, right-handed.
  const Vector toward = options.view / length(options.view);
  Vector up = options.up - (options.up * toward) * toward;
  if(length(up) < 1e-6 * length(options.up))
  {
    // Looking along `up`: any direction across the view will do.
    const Vector axis = std::abs(toward.x()) < 0.9 ? Vector(1, 0, 0) : Vector(0, 1, 0);
    up = axis - (axis * toward) * toward;
  }
  up = up / length(up);
  const Vector right = CGAL::cross_product(up, toward);
  // From the upper left and in front, as most pictures are lit.
  Vector light = -0.35 * right + 0.55 * up + 1.0 * toward;
  light = light / length(light);

  // Orthographic projection of every vertex: picture coordinates and depth (larger is nearer).
  std::vector<double> sx(mesh.num_vertices()), sy(sx.size()), depth(sx.size());
  double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
  for(Mesh::Vertex_index v : mesh.vertices())
  {
    const Vector p = mesh.point(v) - CGAL::ORIGIN;
    sx[v] = p * right;
    sy[v] = p * up;
    depth[v] = p * toward;
    xmin = (std::min)(xmin, sx[v]);
    xmax = (std::max)(xmax, sx[v]);
    ymin = (std::min)(ymin, sy[v]);
    ymax = (std::max)(ymax, sy[v]);
  }

  // A closed surface hides its back faces: they are left out (half the file, and no back face can
  // show through a gap of the painter's order). Its orientation is taken from its signed volume,
  // since a file may list its faces inside out. An open surface shows both sides.
  bool closed = true;
  for(Mesh::Halfedge_index h : mesh.halfedges())
    closed = closed && !mesh.is_border(h);
  double volume = 0;
  for(Mesh::Face_index f : mesh.faces())
  {
    const auto h = mesh.halfedge(f);
    volume += CGAL::scalar_product(mesh.point(mesh.source(h)) - CGAL::ORIGIN,
                                   CGAL::cross_product(mesh.point(mesh.target(h)) - CGAL::ORIGIN,
                                                       mesh.point(mesh.target(mesh.next(h))) - CGAL::ORIGIN));
  }
  const double outward = (closed && volume < 0) ? -1 : 1;

  struct Drawn_face
  {
    double depth;
    std::size_t index;
    std::array<Mesh::Vertex_index, 3> v;
    Rgb colour;
  };
  std::vector<Drawn_face> drawn;
  for(Mesh::Face_index f : mesh.faces())
  {
    const auto h = mesh.halfedge(f);
    const std::array<Mesh::Vertex_index, 3> v = {mesh.source(h), mesh.target(h), mesh.target(mesh.next(h))};
    Vector n = outward * CGAL::cross_product(mesh.point(v[1]) - mesh.point(v[0]), mesh.point(v[2]) - mesh.point(v[0]));
    const double n_length = length(n);
    if(!(n_length > 0))
      continue;
    n = n / n_length;
    if(n * toward < 0)
    {
      if(closed)
        continue;
      n = -n;
    }
    // Lambert: an ambient part, so that faces turned away from the light keep their colour.
    const double shade = 0.32 + 0.68 * (std::max)(0.0, n * light);
    const std::array<double, 3> angles = triangle_angles(mesh, f);
    const Rgb c = angle_colour((std::min)({angles[0], angles[1], angles[2]}));
    drawn.push_back({(depth[v[0]] + depth[v[1]] + depth[v[2]]) / 3, std::size_t(f), v,
                     {c.r * shade, c.g * shade, c.b * shade}});
  }
  // The painter's algorithm: the farthest first. Ties by index, so that the file is repeatable.
  std::sort(drawn.begin(), drawn.end(), [](const Drawn_face& a, const Drawn_face& b) {
    return a.depth != b.depth ? a.depth < b.depth : a.index < b.index;
  });

  // Layout: title, the mesh scaled into the width (but not taller than the width), colour bar.
  const double margin = 12, top = 56, legend = 64;
  const double extent_x = (std::max)(xmax - xmin, 1e-300), extent_y = (std::max)(ymax - ymin, 1e-300);
  double scale = (options.width - 2 * margin) / extent_x;
  scale = (std::min)(scale, (options.width - 2 * margin) / extent_y);
  const double drawing_height = extent_y * scale;
  const double height = top + drawing_height + margin + legend;
  const double x0 = (options.width - extent_x * scale) / 2;
  auto px = [&](Mesh::Vertex_index v) { return coordinate(x0 + (sx[v] - xmin) * scale); };
  auto py = [&](Mesh::Vertex_index v) { return coordinate(top + (ymax - sy[v]) * scale); };

  const PMP::Mesh_quality_report q = PMP::mesh_quality_report(mesh);
  const std::string title = options.title.empty() ? base_name(file) : options.title;
  write_header(out, options.width, height, title,
               std::to_string(q.number_of_vertices) + " vertices, " + std::to_string(q.number_of_faces) +
                 " triangles, mean smallest angle " + fixed(q.mean_min_angle, 2) + "\u00b0",
               "made by render_mesh from " + base_name(file) + ": orthographic view from (" + fixed(options.view.x(), 3) + ", " +
                 fixed(options.view.y(), 3) + ", " + fixed(options.view.z(), 3) + "), up (" +
                 fixed(options.up.x(), 3) + ", " + fixed(options.up.y(), 3) + ", " + fixed(options.up.z(), 3) +
                 "); colour: smallest angle of the triangle");

  // The edges are stroked once for the whole group: no stroke attribute per triangle. Without
  // edges, each triangle is stroked with its own colour, to close the hairline gaps that
  // anti-aliasing leaves between neighbours.
  if(options.edges)
    out << "<g stroke=\"#1c1c1c\" stroke-opacity=\"0.5\" stroke-width=\"0.3\" stroke-linejoin=\"round\">\n";
  else
    out << "<g stroke-width=\"0.4\" stroke-linejoin=\"round\">\n";
  for(const Drawn_face& d : drawn)
  {
    const std::string colour = hex(d.colour);
    out << "<path d=\"M" << px(d.v[0]) << ' ' << py(d.v[0]) << 'L' << px(d.v[1]) << ' ' << py(d.v[1]) << 'L'
        << px(d.v[2]) << ' ' << py(d.v[2]) << "z\" fill=\"" << colour << '"';
    if(!options.edges)
      out << " stroke=\"" << colour << '"';
    out << "/>\n";
  }
  out << "</g>\n";

  // The colour bar: a gradient with the stops of the scale, ticks every 10 degrees.
  const double bar_width = (std::min)(360.0, options.width - 2 * margin), bar_height = 12;
  const double bar_x = (options.width - bar_width) / 2, bar_y = top + drawing_height + margin + 8;
  out << "<defs><linearGradient id=\"angle_scale\" x1=\"0\" x2=\"1\" y1=\"0\" y2=\"0\">";
  for(const Colour_stop& s : angle_scale)
    out << "<stop offset=\"" << fixed(s.angle / max_scale_angle, 4) << "\" stop-color=\"" << hex(s.colour) << "\"/>";
  out << "</linearGradient></defs>\n"
      << "<rect x=\"" << coordinate(bar_x) << "\" y=\"" << coordinate(bar_y) << "\" width=\"" << coordinate(bar_width)
      << "\" height=\"" << coordinate(bar_height) << "\" fill=\"url(#angle_scale)\" stroke=\"#444444\" stroke-width=\"0.5\"/>\n"
      << "<g font-size=\"11\" fill=\"#333333\" text-anchor=\"middle\">\n";
  for(int a = 0; a <= int(max_scale_angle); a += 10)
  {
    const double x = bar_x + bar_width * a / max_scale_angle;
    out << "<path d=\"M" << coordinate(x) << ' ' << coordinate(bar_y + bar_height) << "v4\" stroke=\"#444444\"/>"
        << "<text x=\"" << coordinate(x) << "\" y=\"" << coordinate(bar_y + bar_height + 16) << "\">" << a
        << "\u00b0</text>\n";
  }
  out << "<text x=\"" << coordinate(options.width / 2) << "\" y=\"" << coordinate(bar_y + bar_height + 32)
      << "\">smallest angle of the triangle</text>\n</g>\n</svg>\n";
}

// ---------------------------------------------------------------------------------------------
// The histogram

struct Histogram_options
{
  bool all_angles = false;
  double bin = 0; // 0: the default of the mode
  std::vector<std::string> labels;
  double width = 640;
  std::string title;
};

// A round step for about `count` ticks over [0, top]: 1, 2 or 5 times a power of ten.
double tick_step(double top, int count)
{
  const double raw = top / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for(double m : {1.0, 2.0, 5.0})
    if(m * power >= raw)
      return m * power;
  return 10 * power;
}

void write_histogram(std::ostream& out, const std::vector<tools::Mesh>& meshes, const std::vector<std::string>& files,
                     const Histogram_options& options)
{
  // One colour a mesh: the first (typically the input) a muted blue-grey, the second (the
  // remeshed one) a strong orange, then two more for comparisons.
  const char* const colours[] = {"#6f7f99", "#e0642a", "#2a9d6f", "#9c4fb8"};
  const double range = options.all_angles ? 180 : 60;
  const double bin = options.bin > 0 ? options.bin : (options.all_angles ? 2 : 1);
  const std::size_t bins = std::size_t(std::ceil(range / bin - 1e-9));

  std::vector<std::vector<double> > shares(meshes.size(), std::vector<double>(bins, 0));
  std::vector<double> means(meshes.size(), 0), smallest(meshes.size(), 0), largest(meshes.size(), 0);
  std::vector<std::size_t> counts(meshes.size(), 0);
  double top_share = 0;
  for(std::size_t m = 0; m < meshes.size(); ++m)
  {
    std::vector<double> values;
    for(tools::Mesh::Face_index f : meshes[m].faces())
    {
      const std::array<double, 3> a = triangle_angles(meshes[m], f);
      if(options.all_angles)
        values.insert(values.end(), a.begin(), a.end());
      else
        values.push_back((std::min)({a[0], a[1], a[2]}));
    }
    for(double x : values)
      shares[m][(std::min)(bins - 1, std::size_t((std::max)(0.0, x) / bin))] += 100.0 / double(values.size());
    counts[m] = values.size();
    means[m] = std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
    smallest[m] = *std::min_element(values.begin(), values.end());
    largest[m] = *std::max_element(values.begin(), values.end());
    top_share = (std::max)(top_share, *std::max_element(shares[m].begin(), shares[m].end()));
  }

  // Layout: title and legend, then the plot with its axes.
  const double legend_top = 56, legend_line = 17;
  const double left = 58, right = 18, plot_top = legend_top + legend_line * double(meshes.size()) + 14;
  const double plot_width = options.width - left - right, plot_height = 0.5 * options.width;
  const double bottom = plot_top + plot_height, height = bottom + 46;
  const double y_step = tick_step(top_share, 5);
  const double y_top = y_step * std::ceil(top_share * 1.05 / y_step);
  auto x_of = [&](double angle) { return left + plot_width * angle / range; };
  auto y_of = [&](double share) { return bottom - plot_height * share / y_top; };

  const std::string what = options.all_angles ? "angles" : "triangles";
  write_header(out, options.width, height, options.title.empty() ? "Angles of the triangles" : options.title,
               options.all_angles ? "distribution of all angles of the triangles, bins of " + fixed(bin, 1) + "\u00b0"
                                  : "distribution of the smallest angle of each triangle, bins of " + fixed(bin, 1) + "\u00b0",
               "made by render_mesh: histogram of the " + std::string(options.all_angles ? "angles" : "smallest angles") + " of " +
                 [&] {
                   std::string names;
                   for(const std::string& f : files)
                     names += (names.empty() ? "" : ", ") + base_name(f);
                   return names;
                 }());

  // Grid and axes.
  out << "<g font-size=\"11\" fill=\"#333333\">\n";
  for(double s = 0; s <= y_top + 1e-9; s += y_step)
    out << "<path d=\"M" << coordinate(left) << ' ' << coordinate(y_of(s)) << "H" << coordinate(left + plot_width)
        << "\" stroke=\"" << (s == 0 ? "#444444" : "#e3e3e3") << "\"/><text x=\"" << coordinate(left - 6) << "\" y=\""
        << coordinate(y_of(s) + 4) << "\" text-anchor=\"end\">" << fixed(s, y_step < 1 ? 1 : 0) << "</text>\n";
  const int x_step = options.all_angles ? 30 : 10;
  for(int a = 0; a <= int(range); a += x_step)
    out << "<path d=\"M" << coordinate(x_of(a)) << ' ' << coordinate(bottom) << "v5\" stroke=\"#444444\"/><text x=\""
        << coordinate(x_of(a)) << "\" y=\"" << coordinate(bottom + 18) << "\" text-anchor=\"middle\">" << a
        << "\u00b0</text>\n";
  out << "<text x=\"" << coordinate(left + plot_width / 2) << "\" y=\"" << coordinate(bottom + 36)
      << "\" text-anchor=\"middle\">" << (options.all_angles ? "angle" : "smallest angle of the triangle") << "</text>\n"
      << "<text transform=\"translate(16 " << coordinate(plot_top + plot_height / 2)
      << ") rotate(-90)\" text-anchor=\"middle\">share of the " << what << " (%)</text>\n";
  if(options.all_angles)
    out << "<path d=\"M" << coordinate(x_of(60)) << ' ' << coordinate(plot_top) << "V" << coordinate(bottom)
        << "\" stroke=\"#888888\" stroke-dasharray=\"2 3\"/><text x=\"" << coordinate(x_of(60) + 4) << "\" y=\""
        << coordinate(plot_top + 10) << "\" fill=\"#666666\">equilateral</text>\n";
  out << "</g>\n";

  // One filled step curve a mesh, translucent so that they show through each other, then its
  // outline and, for the smallest angles, a dashed line at the mean.
  for(std::size_t m = 0; m < meshes.size(); ++m)
  {
    const char* colour = colours[m % 4];
    std::ostringstream steps;
    for(std::size_t b = 0; b < bins; ++b)
      steps << 'H' << coordinate(x_of((std::min)(range, double(b) * bin))) << 'V' << coordinate(y_of(shares[m][b]));
    steps << 'H' << coordinate(x_of(range)) << 'V' << coordinate(bottom);
    out << "<path d=\"M" << coordinate(left) << ' ' << coordinate(bottom) << steps.str() << "z\" fill=\"" << colour
        << "\" fill-opacity=\"0.3\" stroke=\"none\"/>\n"
        << "<path d=\"M" << coordinate(left) << ' ' << coordinate(bottom) << steps.str() << "\" fill=\"none\" stroke=\""
        << colour << "\" stroke-width=\"1.5\" stroke-linejoin=\"round\"/>\n";
    if(!options.all_angles)
      out << "<path d=\"M" << coordinate(x_of(means[m])) << ' ' << coordinate(plot_top) << "V" << coordinate(bottom)
          << "\" stroke=\"" << colour << "\" stroke-width=\"1.2\" stroke-dasharray=\"5 3\"/>\n";
  }

  // The legend, one line a mesh.
  out << "<g font-size=\"12\" fill=\"#222222\">\n";
  for(std::size_t m = 0; m < meshes.size(); ++m)
  {
    const double y = legend_top + legend_line * double(m);
    const std::string label = m < options.labels.size() ? options.labels[m] : base_name(files[m]);
    const std::string figures =
      options.all_angles
        ? std::to_string(counts[m]) + " angles, from " + fixed(smallest[m], 2) + "\u00b0 to " + fixed(largest[m], 2) + "\u00b0"
        : std::to_string(counts[m]) + " triangles, mean " + fixed(means[m], 2) + "\u00b0 (dashed), smallest " +
            fixed(smallest[m], 2) + "\u00b0";
    out << "<rect x=\"" << coordinate(left) << "\" y=\"" << coordinate(y) << "\" width=\"14\" height=\"10\" fill=\""
        << colours[m % 4] << "\" fill-opacity=\"0.6\" stroke=\"" << colours[m % 4] << "\"/><text x=\""
        << coordinate(left + 20) << "\" y=\"" << coordinate(y + 9.5) << "\"><tspan font-weight=\"bold\">"
        << escape_xml(label) << "</tspan>: " << figures << "</text>\n";
  }
  out << "</g>\n</svg>\n";
}

// ---------------------------------------------------------------------------------------------

[[noreturn]] void refuse(const std::string& message)
{
  std::cerr << "render_mesh: " << message << '\n';
  std::exit(EXIT_FAILURE);
}

double parse_number(const std::string& option, const char* text)
{
  try
  {
    std::size_t used = 0;
    const double x = std::stod(text, &used);
    if(used == std::string(text).size() && std::isfinite(x))
      return x;
  }
  catch(const std::exception&)
  {
  }
  refuse(option + " needs a number, not '" + text + "'");
}

} // namespace

int main(int argc, char** argv)
{
  Picture_options picture;
  Histogram_options histogram;
  bool histogram_mode = false, size_given = false;
  std::string title;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto need = [&](int count) {
      if(i + count >= argc)
        refuse(arg + " needs " + std::to_string(count) + (count == 1 ? " value" : " values") + " (see --help)");
    };
    auto direction = [&]() {
      need(3);
      const double x = parse_number(arg, argv[i + 1]), y = parse_number(arg, argv[i + 2]), z = parse_number(arg, argv[i + 3]);
      i += 3;
      if(x == 0 && y == 0 && z == 0)
        refuse(arg + " needs a non-zero direction");
      return Vector(x, y, z);
    };
    if(arg == "--help" || arg == "-h")
    {
      std::cout << usage;
      return EXIT_SUCCESS;
    }
    else if(arg == "--histogram") histogram_mode = true;
    else if(arg == "--view") picture.view = direction();
    else if(arg == "--up") picture.up = direction();
    else if(arg == "--no-edges") picture.edges = false;
    else if(arg == "--all-angles") histogram.all_angles = true;
    else if(arg == "--bin")
    {
      need(1);
      histogram.bin = parse_number(arg, argv[++i]);
      if(!(histogram.bin >= 0.1 && histogram.bin <= 30))
        refuse("--bin needs a width between 0.1 and 30 degrees");
    }
    else if(arg == "--label")
    {
      need(1);
      histogram.labels.push_back(argv[++i]);
    }
    else if(arg == "--size")
    {
      need(1);
      const double w = parse_number(arg, argv[++i]);
      if(!(w >= 100 && w <= 10000))
        refuse("--size needs a width between 100 and 10000 pixels");
      picture.width = histogram.width = w;
      size_given = true;
    }
    else if(arg == "--title")
    {
      need(1);
      title = argv[++i];
    }
    else if(arg.size() > 1 && arg[0] == '-')
      refuse("unknown option " + arg + " (see --help)");
    else
      files.push_back(arg);
  }
  if(files.size() < 2 || (!histogram_mode && files.size() != 2))
  {
    std::cerr << "render_mesh: expected " << (histogram_mode ? "MESH [MESH ...] OUTPUT.svg" : "MESH and OUTPUT.svg")
              << " (see --help)\n"
              << usage;
    return EXIT_FAILURE;
  }
  // The last argument is written: refuse anything that does not look like a picture, so that a
  // forgotten OUTPUT never overwrites a mesh.
  const std::string output = files.back();
  files.pop_back();
  if(output.size() < 5 || output.compare(output.size() - 4, 4, ".svg") != 0)
    refuse(output + ": the output must be an .svg file");
  if(histogram.labels.size() > files.size())
    refuse("more --label than meshes");
  picture.title = histogram.title = title;
  if(!size_given)
    histogram.width = 640;

  try
  {
    std::vector<tools::Mesh> meshes;
    for(const std::string& file : files)
    {
      std::vector<std::string> notices;
      meshes.push_back(tools::read_mesh(file, true, &notices));
      for(const std::string& n : notices)
        std::cerr << "render_mesh: " << n << '\n';
    }
    std::ostringstream svg;
    if(histogram_mode)
      write_histogram(svg, meshes, files, histogram);
    else
      write_picture(svg, meshes.front(), files.front(), picture);
    std::ofstream out(output, std::ios::binary);
    out << svg.str();
    if(!out)
      refuse(output + ": cannot write");
  }
  catch(const tools::Input_error& e)
  {
    refuse(e.what());
  }
  return EXIT_SUCCESS;
}
