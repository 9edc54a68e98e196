// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The counts a mesh file declares (its points and faces, the sides of each face, the items of a
// PLY list, a binary STL's triangles) checked against what the file can hold, before CGAL's
// readers size their arrays by them: CGAL's OFF reader resizes its polygons to the declared face
// count and each polygon to its declared number of sides, its PLY reader each list to its count,
// so one wrong number in a small file asks for gigabytes. The check reads the file once, as the
// reader will, keeping nothing but the position: its time and memory are bounded by the file's size.

#ifndef CGAL_GRAPHCUT_REMESHING_DECLARED_COUNTS_H
#define CGAL_GRAPHCUT_REMESHING_DECLARED_COUNTS_H

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <streambuf>
#include <string>
#include <vector>

namespace graphcut_remeshing_tools {
namespace declared_counts {

// The file as a stream of bytes and of words, with the count of bytes still to come.
class Scanner
{
public:
  Scanner(std::streambuf* buffer, std::uintmax_t size) : m_buffer(buffer), m_size(size) {}

  std::uintmax_t remaining() const { return m_size > m_read ? m_size - m_read : 0; }

  // The next word after white space (and, with `comments`, '#' comments to the end of their
  // line); false at the end of the file. The white space after the word is not read.
  bool word(std::string& w, bool comments)
  {
    w.clear();
    int c = peek();
    while(c != EOF && (std::isspace(c) || (comments && c == '#')))
    {
      if(c == '#')
        skip_line();
      else
        get();
      c = peek();
    }
    while(c != EOF && !std::isspace(c) && !(comments && c == '#'))
    {
      if(w.size() < 64) // a count or a keyword; the rest of a longer word does not matter
        w.push_back(char(c));
      get();
      c = peek();
    }
    return !w.empty();
  }

  // The next word as a count: false when it is not a non-negative integer.
  bool count(std::uintmax_t& n, bool comments)
  {
    std::string w;
    if(!word(w, comments) || w.empty() || w.size() > 19 || w.find_first_not_of("0123456789") != std::string::npos)
      return false;
    n = std::strtoull(w.c_str(), nullptr, 10);
    return true;
  }

  void skip_line()
  {
    int c = get();
    while(c != EOF && c != '\n')
      c = get();
  }

  // `bytes` bytes as an unsigned integer in the given byte order; false at the end of the file.
  bool integer(std::size_t bytes, bool big_endian, std::uintmax_t& n)
  {
    unsigned char b[8] = {};
    if(bytes > 8 || std::uintmax_t(m_buffer->sgetn(reinterpret_cast<char*>(b), std::streamsize(bytes))) != bytes)
      return false;
    m_read += bytes;
    n = 0;
    for(std::size_t i = 0; i < bytes; ++i)
      n |= std::uintmax_t(b[big_endian ? bytes - 1 - i : i]) << (8 * i);
    return true;
  }

  bool skip(std::uintmax_t bytes)
  {
    if(bytes > remaining())
      return false;
    m_buffer->pubseekoff(std::streamoff(bytes), std::ios_base::cur, std::ios_base::in);
    m_read += bytes;
    return true;
  }

  int get()
  {
    const int c = m_buffer->sbumpc();
    if(c != EOF)
      ++m_read;
    return c;
  }

private:
  int peek() { return m_buffer->sgetc(); }

  std::streambuf* m_buffer;
  std::uintmax_t m_size;
  std::uintmax_t m_read = 0;
};

// "declares N <what>, but the B bytes that follow hold at most M", or empty when N fits: each
// item takes at least `bytes_each` bytes.
inline std::string too_many(std::uintmax_t n, const std::string& what, std::uintmax_t bytes_each, std::uintmax_t room)
{
  if(n <= room / bytes_each)
    return std::string();
  return "declares " + std::to_string(n) + " " + what + ", but the " + std::to_string(room) +
         " bytes that follow hold at most " + std::to_string(room / bytes_each);
}

// An ASCII OFF file after its first count `nv`: "3 0 1 2" is the shortest face with three sides,
// "0 0 0" the shortest point; every word takes at least two bytes with its separator.
inline std::string check_ascii_off(Scanner& s, std::size_t coordinates, std::uintmax_t nv)
{
  std::uintmax_t nf = 0;
  std::string w;
  if(!s.count(nf, true) || !s.word(w, true)) // the edge count, which the readers ignore
    return std::string(); // not for this check: CGAL's reader says what is wrong
  std::string why = too_many(nv, "vertices", 2 * coordinates, s.remaining());
  if(why.empty())
    why = too_many(nf, "faces", 2, s.remaining());
  if(!why.empty())
    return why;
  s.skip_line();
  // As CGAL's scanner reads: the coordinates of a point, then the rest of its line; the size of a
  // face, its indices, then the rest of its line.
  for(std::uintmax_t v = 0; v < nv; ++v)
  {
    for(std::size_t c = 0; c < coordinates; ++c)
      if(!s.word(w, true))
        return std::string();
    s.skip_line();
  }
  for(std::uintmax_t f = 0; f < nf; ++f)
  {
    std::uintmax_t sides = 0;
    if(!s.count(sides, true))
      return std::string();
    why = too_many(sides, "vertices", 2, s.remaining());
    if(!why.empty())
      return "face " + std::to_string(f) + " " + why;
    for(std::uintmax_t i = 0; i < sides; ++i)
      if(!s.word(w, true))
        return std::string();
    s.skip_line();
  }
  return std::string();
}

// A binary OFF file: big-endian 32-bit counts, points of three floats, each face its size, its
// indices and a count of colour components that follow.
inline std::string check_binary_off(Scanner& s, bool plain, bool dimensional)
{
  std::uintmax_t dimension = 0, nv = 0, nf = 0, ne = 0;
  if((dimensional && !s.integer(4, true, dimension)) || !s.integer(4, true, nv) || !s.integer(4, true, nf) || !s.integer(4, true, ne))
    return std::string();
  std::string why = too_many(nv, "vertices", 12, s.remaining());
  if(why.empty())
    why = too_many(nf, "faces", 8, s.remaining());
  if(!why.empty() || !plain || !s.skip(12 * nv)) // points with normals or colours: the counts only
    return why;
  for(std::uintmax_t f = 0; f < nf; ++f)
  {
    std::uintmax_t sides = 0, colours = 0;
    if(!s.integer(4, true, sides))
      return std::string();
    why = too_many(sides, "vertices", 4, s.remaining());
    if(!why.empty())
      return "face " + std::to_string(f) + " " + why;
    if(!s.skip(4 * sides) || !s.integer(4, true, colours))
      return std::string();
    why = too_many(colours, "colour components", 4, s.remaining());
    if(!why.empty())
      return "face " + std::to_string(f) + " " + why;
    s.skip(4 * colours);
  }
  return std::string();
}

// An OFF header: [ST][C][N][4][n]OFF, then BINARY or the counts (after the dimension for nOFF).
inline std::string check_off(Scanner& s)
{
  std::string keyword, next;
  if(!s.word(keyword, true) || keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0 ||
     !s.word(next, true))
    return std::string();
  const std::string flags = keyword.substr(0, keyword.size() - 3);
  const bool dimensional = flags.find('n') != std::string::npos;
  if(next == "BINARY")
  {
    s.skip_line();
    return check_binary_off(s, flags.empty(), dimensional);
  }
  std::uintmax_t dimension = 3, nv = 0;
  if(next.find_first_not_of("0123456789") != std::string::npos || next.size() > 19)
    return std::string();
  nv = std::strtoull(next.c_str(), nullptr, 10);
  if(dimensional)
  {
    dimension = nv;
    if(dimension == 0 || dimension > 64 || !s.count(nv, true))
      return std::string();
  }
  const std::size_t coordinates = std::size_t(dimension) + (flags.find('4') != std::string::npos ? 1 : 0);
  return check_ascii_off(s, coordinates, nv);
}

inline std::size_t ply_type_size(const std::string& type)
{
  if(type == "char" || type == "uchar" || type == "int8" || type == "uint8")
    return 1;
  if(type == "short" || type == "ushort" || type == "int16" || type == "uint16")
    return 2;
  if(type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
    return 4;
  if(type == "double" || type == "float64")
    return 8;
  return 0;
}

struct Ply_property
{
  std::size_t size = 0;       // of the value, or of a list's items
  std::size_t count_size = 0; // of a list's count; 0 for a value
  bool signed_count = false;
};

struct Ply_element
{
  std::string name;
  std::uintmax_t count = 0;
  std::vector<Ply_property> properties;
};

// The header of a PLY file up to end_header; false if it is not one this check can read.
inline bool read_ply_header(Scanner& s, int& format, std::vector<Ply_element>& elements)
{
  std::string w;
  if(!s.word(w, false) || w != "ply")
    return false;
  format = -1; // 0: ascii, 1: binary little endian, 2: binary big endian
  while(s.word(w, false))
  {
    if(w == "end_header")
    {
      s.skip_line();
      return format >= 0;
    }
    if(w == "format" && s.word(w, false))
      format = w == "ascii" ? 0 : w == "binary_little_endian" ? 1 : w == "binary_big_endian" ? 2 : -1;
    else if(w == "element")
    {
      Ply_element e;
      if(!s.word(e.name, false) || !s.count(e.count, false))
        return false;
      elements.push_back(e);
    }
    else if(w == "property" && !elements.empty() && s.word(w, false))
    {
      Ply_property p;
      if(w == "list")
      {
        std::string count_type, item_type;
        if(!s.word(count_type, false) || !s.word(item_type, false))
          return false;
        p.count_size = ply_type_size(count_type);
        p.signed_count = count_type.find('u') == std::string::npos;
        p.size = ply_type_size(item_type);
      }
      else
        p.size = ply_type_size(w);
      if(p.size == 0 || (p.count_size == 0 && w == "list"))
        return false;
      elements.back().properties.push_back(p);
    }
    s.skip_line(); // the rest of the line: a property's name, a comment
  }
  return false;
}

// One value of a PLY body: a list's count, checked against what is left; false at the end.
inline bool read_ply_list_count(Scanner& s, int format, const Ply_property& p, std::uintmax_t& n, std::string& why)
{
  if(format == 0)
    return s.count(n, false);
  if(!s.integer(p.count_size, format == 2, n))
    return false;
  if(p.signed_count && (n >> (8 * p.count_size - 1)) != 0)
  {
    why = "declares a list of negative size";
    return false;
  }
  return true;
}

inline std::string check_ply(Scanner& s)
{
  int format = -1;
  std::vector<Ply_element> elements;
  if(!read_ply_header(s, format, elements))
    return std::string();
  for(const Ply_element& e : elements)
  {
    std::uintmax_t least = 0; // bytes of one item
    for(const Ply_property& p : e.properties)
      least += format == 0 ? 2 : (p.count_size > 0 ? p.count_size : p.size);
    const std::string why = too_many(e.count, e.name + " items", (std::max)(least, std::uintmax_t(1)), s.remaining());
    if(!why.empty())
      return why;
  }
  std::string w;
  for(const Ply_element& e : elements)
    for(std::uintmax_t item = 0; item < e.count; ++item)
      for(const Ply_property& p : e.properties)
      {
        if(p.count_size == 0)
        {
          if(format == 0 ? !s.word(w, false) : !s.skip(p.size))
            return std::string();
          continue;
        }
        std::uintmax_t n = 0;
        std::string why;
        if(!read_ply_list_count(s, format, p, n, why))
          return why;
        why = too_many(n, "values", format == 0 ? 2 : p.size, s.remaining());
        if(!why.empty())
          return e.name + " " + std::to_string(item) + " " + why;
        for(std::uintmax_t i = 0; i < n; ++i)
          if(format == 0 ? !s.word(w, false) : !s.skip(p.size))
            return std::string();
      }
  return std::string();
}

// A binary STL file (one that does not start with "solid "): an 80-byte header, the triangle
// count, 50 bytes a triangle. CGAL's reader tries an ASCII reading when the binary one fails.
inline std::string check_stl(Scanner& s)
{
  std::string start(6, '\0');
  for(char& c : start)
    c = char(s.get());
  if(start.compare(0, 5, "solid") == 0 && std::isspace(static_cast<unsigned char>(start[5])))
    return std::string();
  std::uintmax_t triangles = 0;
  if(!s.skip(80 - 6) || !s.integer(4, false, triangles))
    return std::string();
  return too_many(triangles, "triangles", 50, s.remaining());
}

} // namespace declared_counts

// Why the counts that the file at `path` declares cannot be, or an empty string: a file whose
// counts it can hold, or one in a format without counts (OBJ), is left to CGAL's reader.
inline std::string impossible_declared_count(const std::string& path)
{
  namespace dc = declared_counts;
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  std::ifstream in(path, std::ios::binary);
  if(error || !in)
    return std::string();
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  dc::Scanner scanner(in.rdbuf(), size);
  if(extension == ".off")
    return dc::check_off(scanner);
  if(extension == ".ply")
    return dc::check_ply(scanner);
  if(extension == ".stl")
    return dc::check_stl(scanner);
  return std::string();
}

} // namespace graphcut_remeshing_tools

#endif // CGAL_GRAPHCUT_REMESHING_DECLARED_COUNTS_H
