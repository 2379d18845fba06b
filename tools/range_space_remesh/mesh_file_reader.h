// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command-line program's reader: OFF (with C, N, ST, 4 and n prefixes), PLY
// (ascii, binary little and big endian, any element order and property types),
// OBJ and STL (ascii and binary; the corners at one position joined) into a polygon
// soup with its vertex colours, in one pass over the file mapped in memory.
//
// Why hand-written, where CGAL and Debian have readers: CGAL 5.5's readers crash on
// legal PLY files (a face element before the vertex element, float colours), read
// colours only in a second pass through a mesh, and allocate whatever a file's counts
// and list lengths say (a 241-byte PLY took 3.8 GB); assimp, OpenMesh and
// tinyobjloader parse through iostreams and have their own histories of allocations
// driven by file counts. The four formats are small; what matters is that no count
// in a file is trusted: every count and list length is checked against the bytes
// left before anything is allocated, so the soup never takes more than a fixed
// multiple of the file's size (see kMaximum_bytes_per_file_byte), and any byte
// sequence ends in a soup or in one Read_error.

#ifndef RANGE_SPACE_REMESHING_TOOLS_MESH_FILE_READER_H
#define RANGE_SPACE_REMESHING_TOOLS_MESH_FILE_READER_H

#include "mesh_formats.h"

#include <boost/container_hash/hash.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rsr_io {

/// Why a file cannot be read, in one line.
struct Read_error : std::runtime_error
{
  /// `message` with its control characters escaped (\xNN): it quotes bytes of the file,
  /// and a NUL would end what() there, a newline break the program's one-line message.
  explicit Read_error(const std::string& message) : std::runtime_error(escaped(message)) {}

private:
  static std::string escaped(const std::string& message)
  {
    std::string out;
    for(const unsigned char c : message) {
      if(c < 0x20 || c == 0x7f) {
        static const char digits[] = "0123456789abcdef";
        out += {'\\', 'x', digits[c >> 4], digits[c & 15]};
      } else {
        out += char(c);
      }
    }
    return out;
  }
};

/// A point's coordinates as a hash key. Boost's hash gives 0 and -0 one value, as
/// the key's == (which holds between them) requires.
using Position = std::array<double, 3>;
using Position_hash = boost::hash<Position>;

/// What a file holds: points, polygons (indices into `points`, unchecked) and, if
/// the file has vertex colours, one colour per point (red, green, blue in 0..255);
/// if it has texture coordinates and each point has one, one UV per point.
struct Polygon_soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<std::array<unsigned char, 3>> colors; // empty, or one per point
  std::vector<std::array<double, 2>> uvs;           // empty, or one per point
  /// points with several texture coordinates (on a texture seam): the UVs are then
  /// dropped, a vertex map cannot hold them
  std::size_t uv_seam_points = 0;
  /// face corners without a texture coordinate in a file whose other corners have
  /// one: the UVs are then dropped
  std::size_t uv_missing_corners = 0;
  /// points added by Uv_seams::SPLIT
  std::size_t uv_seam_copies = 0;
  /// where the reader took the file otherwise than it says (a binary STL's triangle
  /// count that is not the file's, colours out of their range): one line each for the
  /// user
  std::vector<std::string> notes;
};

/// What to do with a point that an OBJ file's faces give several texture coordinates
/// (f v/vt with different vt at one v: a texture seam).
enum class Uv_seams
{
  /// keep the point, count it in `Polygon_soup::uv_seam_points`: the UVs are dropped
  DROP,
  /// give each of its texture coordinates a copy of the point (at the same position,
  /// with its colour), as PLY files store a seam; counted in `uv_seam_copies`
  SPLIT
};

/// Whether two texture coordinates of one point are the same one: apart by at most a
/// billionth of their size (of 1 if smaller), far below a texel. Exact equality would
/// see seams where an exporter or an interpolation (the program's own output at the
/// copies of a crease) left the UVs of one point a few units in the last place apart.
inline bool same_uv(const std::array<double, 2>& a, const std::array<double, 2>& b)
{
  for(std::size_t k = 0; k < 2; ++k)
    if(!(std::abs(a[k] - b[k]) <= 1e-9 * std::max({1., std::abs(a[k]), std::abs(b[k])})))
      return false;
  return true;
}

/// The largest a soup can be, in bytes of memory per byte of file: a binary PLY face
/// of three one-byte indices (4 bytes of file) becomes a vector of three indices
/// (24 bytes, plus the vector and the allocator's header: about 64 bytes).
constexpr double kMaximum_bytes_per_file_byte = 24;

namespace internal {

/// A regular file mapped read-only in memory.
class Mapped_file
{
public:
  explicit Mapped_file(const std::string& path)
  {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if(fd < 0)
      throw Read_error("cannot open '" + path + "': " + std::strerror(errno));
    struct stat status;
    if(::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode)) {
      ::close(fd);
      throw Read_error("'" + path + "' is not a regular file");
    }
    size_ = std::size_t(status.st_size);
    if(size_ > 0) {
      void* data = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
      if(data == MAP_FAILED) {
        ::close(fd);
        throw Read_error("cannot read '" + path + "': " + std::strerror(errno));
      }
      data_ = static_cast<const char*>(data);
      ::madvise(data, size_, MADV_SEQUENTIAL);
    }
    ::close(fd);
  }
  ~Mapped_file()
  {
    if(data_)
      ::munmap(const_cast<char*>(data_), size_);
  }
  Mapped_file(const Mapped_file&) = delete;
  Mapped_file& operator=(const Mapped_file&) = delete;
  std::string_view text() const { return {data_ ? data_ : "", size_}; }

private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

/// Reads words, numbers and lines from a text; never reads past its end.
class Text_cursor
{
public:
  explicit Text_cursor(std::string_view text) : p_(text.data()), end_(text.data() + text.size()) {}

  std::size_t bytes_left() const { return std::size_t(end_ - p_); }
  const char* position() const { return p_; }
  bool at_end() const { return p_ == end_; }

  /// Skips blanks and, if `comment` is not 0, from `comment` to the end of the line.
  void skip_blanks_in_line(char comment = 0)
  {
    while(p_ != end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\f' || *p_ == '\v'))
      ++p_;
    if(comment && p_ != end_ && *p_ == comment)
      while(p_ != end_ && *p_ != '\n')
        ++p_;
  }
  bool at_line_end(char comment = 0)
  {
    skip_blanks_in_line(comment);
    return p_ == end_ || *p_ == '\n';
  }
  /// Moves to the start of the next line.
  void next_line()
  {
    while(p_ != end_ && *p_ != '\n')
      ++p_;
    if(p_ != end_)
      ++p_;
  }
  /// Skips all whitespace, newlines included.
  void skip_space()
  {
    while(p_ != end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n' || *p_ == '\f' || *p_ == '\v'))
      ++p_;
  }
  /// The next word on this line (empty at the line's end).
  std::string_view word_in_line(char comment = 0)
  {
    skip_blanks_in_line(comment);
    const char* start = p_;
    while(p_ != end_ && !is_space(*p_) && !(comment && *p_ == comment))
      ++p_;
    return {start, std::size_t(p_ - start)};
  }
  /// The next word, across lines.
  std::string_view word()
  {
    skip_space();
    const char* start = p_;
    while(p_ != end_ && !is_space(*p_))
      ++p_;
    return {start, std::size_t(p_ - start)};
  }
  /// The rest of the line, without its end.
  std::string_view rest_of_line()
  {
    const char* start = p_;
    while(p_ != end_ && *p_ != '\n')
      ++p_;
    std::string_view line(start, std::size_t(p_ - start));
    if(!line.empty() && line.back() == '\r')
      line.remove_suffix(1);
    return line;
  }

  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

private:
  const char* p_;
  const char* end_;
};

/// `word` (an optional '+', then what std::from_chars reads) as a number, or false
/// (also on overflow). Doubles may be NaN or infinite: callers check what they need.
template <class Number>
bool parse_number(std::string_view word, Number& value)
{
  if(!word.empty() && word.front() == '+')
    word.remove_prefix(1);
  if(word.empty())
    return false;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  return error == std::errc() && end == word.data() + word.size();
}

inline bool to_double(std::string_view word, double& value) { return parse_number(word, value); }
inline bool to_integer(std::string_view word, long long& value) { return parse_number(word, value); }

/// The range a file's colour channel is in: its numbers are scaled from it to 0..255.
enum class Color_range : std::uint8_t
{
  UNIT_OR_BYTE, // floats: [0, 1], or 0..255 if some exceed 1 (decided once all are read)
  BYTE,         // integers in 0..255
  SIXTEEN_BITS  // 16-bit integers in 0..65535
};

/// The vertex colours of a file as it gives them, made 0..255 once the last is read:
/// floats in [0, 1] unless one exceeds 1 (some writers give floats in 0..255, which
/// scaled by 255 all came out white), integers in 0..255 or, 16-bit ones, in 0..65535;
/// a value still out of 0..255 is clamped. Both are said in a note. Kept as doubles:
/// floats would round some colours differently (0.9 * 255).
class Color_channels
{
public:
  /// The colour of point `point`; the points before it without one (some writers leave
  /// it out) are black.
  void add(std::size_t point, const std::array<double, 3>& values, Color_range range)
  {
    values_.resize(point, {{0, 0, 0}});
    ranges_.resize(point, Color_range::BYTE);
    values_.push_back(values);
    ranges_.push_back(range);
    ++given_;
    const bool above_one = std::any_of(values.begin(), values.end(), [](double x) { return x > 1; });
    if(range == Color_range::UNIT_OR_BYTE) {
      ++floats_;
      floats_above_one_ = floats_above_one_ || above_one;
    } else if(range == Color_range::BYTE) {
      ++integers_;
      integers_above_one_ = integers_above_one_ || above_one;
    }
  }
  bool any() const { return !values_.empty(); }

  /// The colours of the file's `points` points in 0..255, and the notes on how they
  /// were taken.
  std::vector<std::array<unsigned char, 3>> take(std::size_t points, std::vector<std::string>& notes) const
  {
    std::vector<std::array<unsigned char, 3>> colors(points, {{0, 0, 0}});
    // an OFF file decides line by line: "1 0 0" among "0.5 0.5 0.5" lines is the file's
    // [0, 1], not 1/255 (and 255 among floats makes them all 0..255), so the file decides
    const bool mixed = integers_ > 0 && floats_ > 0;
    const bool in_bytes = floats_above_one_ || (mixed && integers_above_one_);
    std::size_t clamped = 0;
    for(std::size_t i = 0; i < values_.size(); ++i) {
      const bool as_float = ranges_[i] == Color_range::UNIT_OR_BYTE || (mixed && ranges_[i] == Color_range::BYTE);
      const double scale = ranges_[i] == Color_range::SIXTEEN_BITS ? 255. / 65535
                           : !as_float || in_bytes               ? 1
                                                                   : 255;
      for(int c = 0; c < 3; ++c) {
        const double x = values_[i][std::size_t(c)] * scale;
        clamped += !(x >= 0 && x <= 255);
        colors[i][std::size_t(c)] = x > 0 ? static_cast<unsigned char>(std::lround((std::min)(x, 255.))) : 0;
      }
    }
    if(mixed)
      notes.push_back(std::string("its colours mix integers and numbers with a decimal point: all taken in ") +
                      (in_bytes ? "0..255" : "[0, 1]"));
    else if(floats_above_one_)
      notes.push_back("its colours, which may be in [0, 1], have values above 1: all taken in 0..255");
    if(given_ < points)
      notes.push_back(std::to_string(points - given_) + " of its " + std::to_string(points) +
                      " vertices have no colour: black");
    if(clamped > 0)
      notes.push_back(std::to_string(clamped) + (clamped == 1 ? " colour value is" : " colour values are") +
                      " outside 0..255: clamped");
    return colors;
  }

private:
  std::vector<std::array<double, 3>> values_; // up to the last point with a colour
  std::vector<Color_range> ranges_;
  std::size_t given_ = 0; // points with a colour
  std::size_t floats_ = 0, integers_ = 0; // of them, given as UNIT_OR_BYTE, as BYTE
  bool integers_above_one_ = false;
  bool floats_above_one_ = false;
};

/// Reserves room for `count` items, but never more than the bytes left could hold
/// at `minimum_bytes` each: a count in a file is a promise, not a fact.
template <class Vector>
void reserve_at_most(Vector& v, std::uint64_t count, std::size_t bytes_left, std::size_t minimum_bytes)
{
  const std::uint64_t possible = bytes_left / std::max<std::size_t>(minimum_bytes, 1);
  v.reserve(std::size_t(std::min(count, possible)));
}

// ------------------------------------------------------------------------ OFF

/// A text OFF file: header "[ST][C][N][4][n]OFF", counts, one vertex per line
/// (position, then normal, colour, texture coordinates as the prefixes say), one
/// face per line (degree, indices, optional colour). Binary OFF is refused.
inline Polygon_soup read_off(std::string_view text, const std::string& name)
{
  Text_cursor in(text);
  auto fail = [&](const std::string& what) -> void { throw Read_error(name + ": " + what); };
  auto next_content_line = [&] { // skips empty and comment lines
    while(!in.at_end() && in.at_line_end('#'))
      in.next_line();
  };
  next_content_line();
  const std::string_view keyword = in.word_in_line('#');
  if(keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF")
    fail("not an OFF file (no OFF keyword on its first line)");
  std::string_view prefix = keyword.substr(0, keyword.size() - 3);
  auto take = [&prefix](std::string_view p) {
    if(prefix.substr(0, p.size()) != p)
      return false;
    prefix.remove_prefix(p.size());
    return true;
  };
  const bool has_texture = take("ST"), has_color = take("C"), has_normal = take("N"), homogeneous = take("4"),
             has_dimension = take("n");
  if(!prefix.empty())
    fail("unknown OFF keyword '" + std::string(keyword) + "'");
  const Text_cursor after_keyword = in; // the counts may follow on the keyword's line
  if(in.word_in_line('#') == "BINARY")
    fail("binary OFF is not supported (convert it to text OFF, PLY or STL)");
  in = after_keyword;
  std::vector<long long> header; // [dimension,] vertices, faces, edges
  const std::size_t wanted = has_dimension ? 3 : 2;      // the edge count is optional
  while(header.size() < wanted && !in.at_end()) {
    std::string_view w = in.word_in_line('#');
    if(w.empty()) {
      in.next_line();
      next_content_line();
      continue;
    }
    long long n = 0;
    if(!to_integer(w, n) || n < 0)
      fail("its header has a count that is not a non-negative integer ('" + std::string(w) + "')");
    header.push_back(n);
  }
  if(header.size() < wanted)
    fail("its header is truncated");
  if(has_dimension && header[0] != 3)
    fail("only 3-dimensional nOFF files are supported (dimension " + std::to_string(header[0]) + ")");
  const long long vertex_count = header[wanted - 2], face_count = header[wanted - 1];
  if(std::uint64_t(vertex_count) > in.bytes_left() || std::uint64_t(face_count) > in.bytes_left())
    fail("its header's counts are larger than the file could hold");
  in.next_line(); // the rest of the header line (the edge count)

  Polygon_soup soup;
  reserve_at_most(soup.points, std::uint64_t(vertex_count), in.bytes_left(), 6);
  const std::size_t position_size = homogeneous ? 4 : 3;
  Color_channels colors;
  for(long long v = 0; v < vertex_count; ++v) {
    next_content_line();
    if(in.at_end())
      fail("it ends before its " + std::to_string(vertex_count) + " vertices");
    double x[4] = {0, 0, 0, 1};
    for(std::size_t c = 0; c < position_size; ++c)
      if(!to_double(in.word_in_line('#'), x[c]))
        fail("vertex " + std::to_string(v) + " has a coordinate that is not a number");
    if(homogeneous) {
      if(x[3] == 0)
        fail("vertex " + std::to_string(v) + " has a homogeneous coordinate of 0");
      x[0] /= x[3], x[1] /= x[3], x[2] /= x[3];
    }
    soup.points.push_back({{x[0], x[1], x[2]}});
    if(has_normal)
      for(int c = 0; c < 3; ++c)
        in.word_in_line('#');
    if(has_color && !in.at_line_end('#')) { // r g b [a], integers in 0..255 or floats in [0, 1]
      // (a vertex without any colour, which some writers leave, keeps black)
      std::array<std::string_view, 3> words{{in.word_in_line('#'), in.word_in_line('#'), in.word_in_line('#')}};
      bool is_float = false;
      std::array<double, 3> values{};
      for(int c = 0; c < 3; ++c) {
        if(!to_double(words[std::size_t(c)], values[std::size_t(c)]))
          fail("vertex " + std::to_string(v) + " has a colour that is not a number");
        is_float = is_float || words[std::size_t(c)].find_first_of(".eE") != std::string_view::npos;
      }
      for(int c = 0; c < 3; ++c)
        if(!std::isfinite(values[std::size_t(c)]))
          fail("vertex " + std::to_string(v) + " has a colour that is not a finite number");
      colors.add(soup.points.size() - 1, values, is_float ? Color_range::UNIT_OR_BYTE : Color_range::BYTE);
    }
    (void)has_texture; // texture coordinates, if any, are the rest of the line
    in.next_line();
  }
  if(colors.any())
    soup.colors = colors.take(soup.points.size(), soup.notes);
  reserve_at_most(soup.polygons, std::uint64_t(face_count), in.bytes_left(), 8);
  for(long long f = 0; f < face_count; ++f) {
    next_content_line();
    if(in.at_end())
      fail("it ends before its " + std::to_string(face_count) + " faces");
    long long degree = 0;
    if(!to_integer(in.word_in_line('#'), degree) || degree < 0)
      fail("face " + std::to_string(f) + " has a degree that is not a non-negative integer");
    if(std::uint64_t(degree) > in.bytes_left() / 2)
      fail("face " + std::to_string(f) + " has more corners than the file could hold");
    std::vector<std::size_t> polygon(static_cast<std::size_t>(degree));
    for(auto& corner : polygon) {
      long long index = 0;
      if(!to_integer(in.word_in_line('#'), index) || index < 0)
        fail("face " + std::to_string(f) + " has an index that is not a non-negative integer");
      corner = std::size_t(index);
    }
    soup.polygons.push_back(std::move(polygon));
    in.next_line();
  }
  return soup;
}

// ------------------------------------------------------------------------ PLY

enum class Ply_type { INT8, UINT8, INT16, UINT16, INT32, UINT32, FLOAT32, FLOAT64 };

inline bool ply_type_of(std::string_view word, Ply_type& type)
{
  static const std::pair<const char*, Ply_type> names[] = {
      {"char", Ply_type::INT8},     {"int8", Ply_type::INT8},       {"uchar", Ply_type::UINT8},
      {"uint8", Ply_type::UINT8},   {"short", Ply_type::INT16},     {"int16", Ply_type::INT16},
      {"ushort", Ply_type::UINT16}, {"uint16", Ply_type::UINT16},   {"int", Ply_type::INT32},
      {"int32", Ply_type::INT32},   {"uint", Ply_type::UINT32},     {"uint32", Ply_type::UINT32},
      {"float", Ply_type::FLOAT32}, {"float32", Ply_type::FLOAT32}, {"double", Ply_type::FLOAT64},
      {"float64", Ply_type::FLOAT64}};
  for(const auto& [n, t] : names)
    if(word == n) {
      type = t;
      return true;
    }
  return false;
}

inline std::size_t ply_size(Ply_type type)
{
  switch(type) {
  case Ply_type::INT8: case Ply_type::UINT8: return 1;
  case Ply_type::INT16: case Ply_type::UINT16: return 2;
  case Ply_type::INT32: case Ply_type::UINT32: case Ply_type::FLOAT32: return 4;
  default: return 8;
  }
}

inline bool is_float(Ply_type type) { return type == Ply_type::FLOAT32 || type == Ply_type::FLOAT64; }

/// The range of a colour channel of this type (see Color_channels).
inline Color_range color_range_of(Ply_type type)
{
  return is_float(type)                                          ? Color_range::UNIT_OR_BYTE
         : type == Ply_type::UINT16 || type == Ply_type::INT16 ? Color_range::SIXTEEN_BITS
                                                                 : Color_range::BYTE;
}

struct Ply_property
{
  std::string name;
  Ply_type type = Ply_type::FLOAT32;
  bool is_list = false;
  Ply_type count_type = Ply_type::UINT8;
};

struct Ply_element
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<Ply_property> properties;

  /// The index of the scalar property `name`, -1 if there is none.
  int scalar(const char* name_) const
  {
    for(std::size_t p = 0; p < properties.size(); ++p)
      if(!properties[p].is_list && properties[p].name == name_)
        return int(p);
    return -1;
  }
};

/// Which property of a PLY element is what: -1 where absent.
struct Ply_roles
{
  int coordinate[3] = {-1, -1, -1}, channel[3] = {-1, -1, -1}, texture[2] = {-1, -1}, indices = -1;
};

/// The first of `families` (names of N properties) whose N names are all scalar
/// properties of `element`, into `index`; left at -1 if none is complete, so that
/// names of different families ("s" and "v", "texture_u" and "t") never pair up.
template <std::size_t N, std::size_t M>
void find_family(const Ply_element& element, const std::array<std::array<const char*, N>, M>& families, int (&index)[N])
{
  for(const auto& family : families) {
    int found[N];
    for(std::size_t k = 0; k < N; ++k)
      found[k] = element.scalar(family[k]);
    if(std::all_of(std::begin(found), std::end(found), [](int i) { return i >= 0; })) {
      std::copy(std::begin(found), std::end(found), index);
      return;
    }
  }
}

/// What the reader takes from `element`: coordinates, colours (red green blue, then
/// diffuse_..., then r g b) and texture coordinates (s t, then u v, texture_u
/// texture_v, texture_s texture_t), and the list of vertex indices.
inline Ply_roles roles_of(const Ply_element& element)
{
  Ply_roles roles;
  find_family<3, 1>(element, {{{"x", "y", "z"}}}, roles.coordinate);
  find_family<3, 3>(element, {{{"red", "green", "blue"}, {"diffuse_red", "diffuse_green", "diffuse_blue"}, {"r", "g", "b"}}},
                    roles.channel);
  find_family<2, 4>(element, {{{"s", "t"}, {"u", "v"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}},
                    roles.texture);
  for(std::size_t p = 0; p < element.properties.size(); ++p)
    if(element.properties[p].is_list &&
       (element.properties[p].name == "vertex_indices" || element.properties[p].name == "vertex_index"))
      roles.indices = int(p);
  return roles;
}

/// Reads the scalars of a binary PLY body.
class Binary_cursor
{
public:
  Binary_cursor(std::string_view bytes, bool big_endian) : p_(bytes.data()), end_(bytes.data() + bytes.size()),
                                                           swap_(big_endian != host_is_big_endian()) {}
  std::size_t bytes_left() const { return std::size_t(end_ - p_); }
  /// The next value of `type` as a double; false if the file ends first.
  bool read(Ply_type type, double& value)
  {
    const std::size_t size = ply_size(type);
    if(bytes_left() < size)
      return false;
    unsigned char b[8];
    std::memcpy(b, p_, size);
    p_ += size;
    if(swap_)
      std::reverse(b, b + size);
    switch(type) {
    case Ply_type::INT8: value = double(static_cast<std::int8_t>(b[0])); break;
    case Ply_type::UINT8: value = double(b[0]); break;
    case Ply_type::INT16: value = double(load<std::int16_t>(b)); break;
    case Ply_type::UINT16: value = double(load<std::uint16_t>(b)); break;
    case Ply_type::INT32: value = double(load<std::int32_t>(b)); break;
    case Ply_type::UINT32: value = double(load<std::uint32_t>(b)); break;
    case Ply_type::FLOAT32: value = double(load<float>(b)); break;
    default: value = load<double>(b); break;
    }
    return true;
  }

private:
  template <class T>
  static T load(const unsigned char* b)
  {
    T t;
    std::memcpy(&t, b, sizeof(T));
    return t;
  }
  static bool host_is_big_endian()
  {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 0;
  }
  const char* p_;
  const char* end_;
  bool swap_;
};

/// Reads the values of a PLY body, ascii or binary, as doubles.
class Ply_values
{
public:
  Ply_values(std::string_view body, int format) : text_(body), binary_(body, format == 2), format_(format) {}
  std::size_t bytes_left() const { return format_ == 0 ? text_.bytes_left() : binary_.bytes_left(); }
  bool read(Ply_type type, double& value)
  {
    if(format_ != 0)
      return binary_.read(type, value);
    return to_double(text_.word(), value);
  }
  /// The fewest bytes a value of `type` takes.
  std::size_t minimum_size(Ply_type type) const { return format_ == 0 ? 2 : ply_size(type); }

private:
  Text_cursor text_;
  Binary_cursor binary_;
  int format_; // 0 ascii, 1 binary little endian, 2 binary big endian
};

/// In a PLY triangle strip, what the file's -1 between two strips becomes.
constexpr std::size_t kStrip_end = std::size_t(-1);

/// The triangles of a PLY triangle strip (`tristrips`, as scanners and VCG write
/// it): kStrip_end ends a strip; every second triangle is turned so that all keep the
/// strip's orientation; a triangle with a repeated corner is how a strip turns or
/// joins the next, not a face, and is skipped. False, and some triangles appended,
/// if there would be more than `most` polygons.
inline bool append_strip_triangles(const std::vector<std::size_t>& strip, std::vector<std::vector<std::size_t>>& polygons,
                                   std::size_t most)
{
  std::size_t begin = 0; // of the current strip
  for(std::size_t i = 0; i < strip.size(); ++i) {
    if(strip[i] == kStrip_end) {
      begin = i + 1;
      continue;
    }
    if(i < begin + 2)
      continue;
    std::size_t a = strip[i - 2], b = strip[i - 1];
    const std::size_t c = strip[i];
    if(a == b || b == c || a == c)
      continue;
    if((i - begin) % 2 == 1)
      std::swap(a, b);
    if(polygons.size() >= most)
      return false;
    polygons.push_back({a, b, c});
  }
  return true;
}

inline Polygon_soup read_ply(std::string_view text, const std::string& name)
{
  auto fail = [&](const std::string& what) -> void { throw Read_error(name + ": " + what); };
  Text_cursor header(text);
  if(header.word_in_line() != "ply")
    fail("not a PLY file (no 'ply' on its first line)");
  header.next_line();
  int format = -1;
  std::vector<Ply_element> elements;
  std::unordered_set<std::string> property_names; // of the last element: a set, as a header may list many
  for(std::size_t line = 2;; ++line, header.next_line()) {
    if(header.at_end())
      fail("its PLY header has no end_header");
    const std::string_view keyword = header.word_in_line();
    const std::string where = " (line " + std::to_string(line) + ")";
    if(keyword == "end_header") {
      header.next_line();
      break;
    }
    if(keyword.empty() || keyword == "comment" || keyword == "obj_info")
      continue;
    if(keyword == "format") {
      const std::string_view kind = header.word_in_line();
      format = kind == "ascii" ? 0 : kind == "binary_little_endian" ? 1 : kind == "binary_big_endian" ? 2 : -1;
      if(format < 0)
        fail("unknown PLY format '" + std::string(kind) + "'" + where);
    } else if(keyword == "element") {
      Ply_element element;
      element.name = std::string(header.word_in_line());
      long long count = -1;
      const std::string_view word = header.word_in_line();
      if(!to_integer(word, count) || count < 0 || std::uint64_t(count) > text.size())
        fail("its PLY element count cannot be right ('" + std::string(word) + "'" + where + ")");
      element.count = std::uint64_t(count);
      elements.push_back(std::move(element));
      property_names.clear();
    } else if(keyword == "property") {
      if(elements.empty())
        fail("it has a PLY property before any element" + where);
      Ply_property property;
      std::string_view type = header.word_in_line();
      if(type == "list") {
        property.is_list = true;
        if(!ply_type_of(header.word_in_line(), property.count_type) || is_float(property.count_type))
          fail("its PLY list has no integer count type" + where);
        type = header.word_in_line();
      }
      if(!ply_type_of(type, property.type))
        fail("unknown PLY property type '" + std::string(type) + "'" + where);
      property.name = std::string(header.word_in_line());
      if(!property_names.insert(property.name).second) // which one would be meant?
        fail("its PLY element '" + elements.back().name + "' has two properties named '" + property.name + "'" +
             where);
      elements.back().properties.push_back(std::move(property));
    } else {
      fail("unknown PLY header keyword '" + std::string(keyword) + "'" + where);
    }
  }
  if(format < 0)
    fail("its PLY header has no format line");

  Polygon_soup soup;
  bool has_vertices = false, has_faces = false, has_strips = false;
  Color_channels colors;
  Ply_values values(text.substr(std::size_t(header.position() - text.data())), format);
  // a triangle takes about 64 bytes, and a strip of one-byte indices makes one per
  // byte: strips could pass the bound of kMaximum_bytes_per_file_byte, faces cannot
  const auto most_strip_triangles = std::size_t(kMaximum_bytes_per_file_byte / 64 * double(text.size()));
  for(const Ply_element& element : elements) {
    const bool is_vertex = element.name == "vertex" && !has_vertices;
    const bool is_face = element.name == "face" && !has_faces;
    const bool is_strips = element.name == "tristrips" && !has_strips;
    has_vertices = has_vertices || is_vertex;
    has_faces = has_faces || is_face;
    has_strips = has_strips || is_strips;
    std::size_t minimum = 0; // the fewest bytes an element of this kind takes
    for(const Ply_property& property : element.properties)
      minimum += values.minimum_size(property.is_list ? property.count_type : property.type);
    if(minimum == 0 ? element.count > 0 : element.count > values.bytes_left() / minimum)
      fail("it has fewer bytes than its " + std::to_string(element.count) + " '" + element.name + "' elements need");
    const Ply_roles roles = roles_of(element);
    const auto& coordinate = roles.coordinate;
    const auto& channel = roles.channel;
    const auto& texture = roles.texture;
    const int indices = roles.indices;
    if(is_vertex && (coordinate[0] < 0 || coordinate[1] < 0 || coordinate[2] < 0))
      fail("its PLY vertices have no x, y and z");
    if((is_face || is_strips) && indices < 0)
      fail("its PLY '" + element.name + "' elements have no vertex_indices list");
    const bool colored = is_vertex && channel[0] >= 0 && channel[1] >= 0 && channel[2] >= 0;
    const bool textured = is_vertex && texture[0] >= 0 && texture[1] >= 0;
    if(is_vertex) {
      reserve_at_most(soup.points, element.count, values.bytes_left(), minimum);
      if(textured)
        reserve_at_most(soup.uvs, element.count, values.bytes_left(), minimum);
    }
    if(is_face)
      reserve_at_most(soup.polygons, element.count, values.bytes_left(), minimum);
    for(std::uint64_t e = 0; e < element.count; ++e) {
      std::array<double, 3> point{};
      std::array<double, 3> color{};
      Color_range color_range = Color_range::BYTE;
      std::array<double, 2> uv{};
      for(std::size_t p = 0; p < element.properties.size(); ++p) {
        const Ply_property& property = element.properties[p];
        double value = 0;
        if(!property.is_list) {
          if(!values.read(property.type, value))
            fail("its '" + element.name + "' element " + std::to_string(e) + " is truncated or not a number");
          for(int c = 0; c < 3; ++c) {
            if(coordinate[c] == int(p))
              point[std::size_t(c)] = value;
            if(channel[c] == int(p)) {
              if(colored && !std::isfinite(value))
                fail("its vertex " + std::to_string(e) + " has a colour that is not a finite number");
              color[std::size_t(c)] = value;
              color_range = color_range_of(property.type);
            }
          }
          for(int c = 0; c < 2; ++c)
            if(texture[c] == int(p) && is_vertex) {
              if(!std::isfinite(value))
                fail("its vertex " + std::to_string(e) + " has a texture coordinate that is not a finite number");
              uv[std::size_t(c)] = value;
            }
          continue;
        }
        double length = 0;
        if(!values.read(property.count_type, length) || length < 0)
          fail("its '" + element.name + "' element " + std::to_string(e) + " has no valid list length");
        if(length > double(values.bytes_left() / values.minimum_size(property.type)))
          fail("its '" + element.name + "' element " + std::to_string(e) + " has a list longer than the file");
        const bool is_corner_list = int(p) == indices && (is_face || is_strips);
        std::vector<std::size_t> corners;
        if(is_corner_list)
          corners.reserve(std::size_t(length));
        for(std::size_t i = 0; i < std::size_t(length); ++i) {
          if(!values.read(property.type, value))
            fail("its '" + element.name + "' element " + std::to_string(e) + " is truncated or not a number");
          if(is_corner_list) {
            if(!(value >= (is_strips ? -1 : 0) && value < 1e15) || value != std::floor(value))
              fail(std::string(is_strips ? "triangle strip " : "face ") + std::to_string(e) +
                   " has an index that is not a non-negative integer" + (is_strips ? " or -1" : ""));
            corners.push_back(value < 0 ? kStrip_end : std::size_t(value));
          }
        }
        if(is_corner_list && is_face)
          soup.polygons.push_back(std::move(corners));
        if(is_corner_list && is_strips && !append_strip_triangles(corners, soup.polygons, most_strip_triangles))
          fail("its triangle strips make more triangles than the reader holds for a file of " +
               std::to_string(text.size()) + " bytes");
      }
      if(is_vertex) {
        soup.points.push_back(point);
        if(colored)
          colors.add(soup.points.size() - 1, color, color_range);
        if(textured)
          soup.uvs.push_back(uv);
      }
    }
  }
  if(!has_vertices)
    fail("it has no PLY vertex element");
  if(colors.any())
    soup.colors = colors.take(soup.points.size(), soup.notes);
  return soup;
}

// ------------------------------------------------------------------------ OBJ

/// A corner of an OBJ face, "v", "v/t", "v//n" or "v/t/n": its indices as written
/// (counted from 1; negative: back from the last one read), 0 where absent.
struct Obj_corner
{
  long long v = 0, t = 0, n = 0;
};

/// `word` as a corner; false unless it has one of the four forms with non-zero
/// integers ("1/1/1/1", "1/x", "1/1.5", "0" and "/1" are not corners). An empty field
/// after a slash is absent ("1/", "1//" and "1/1/", as some exporters write them).
inline bool parse_obj_corner(std::string_view word, Obj_corner& corner)
{
  long long* fields[3] = {&corner.v, &corner.t, &corner.n};
  for(std::size_t k = 0; k < 3; ++k) {
    const auto slash = word.find('/');
    const std::string_view field = word.substr(0, slash);
    if(!(k > 0 && field.empty()) && (!to_integer(field, *fields[k]) || *fields[k] == 0))
      return false;
    if(slash == std::string_view::npos)
      return true;
    word.remove_prefix(slash + 1);
  }
  return false; // a fourth field
}

/// An OBJ index (see Obj_corner) among the `count` items read so far, from 1; 0 if
/// it refers to none of them.
inline std::size_t resolved_obj_index(long long index, std::size_t count)
{
  const long long n = static_cast<long long>(count);
  if(index < 0)
    index += n + 1;
  return index >= 1 && index <= n ? std::size_t(index) : 0;
}

/// The point of a corner with texture coordinate `uv` (1-based) at `point`: `point`,
/// or its copy with that UV (made on the first such corner), for Uv_seams::SPLIT.
class Uv_seam_copies
{
public:
  Uv_seam_copies(const std::vector<std::array<double, 2>>& texture_coordinates, std::vector<std::size_t>& uv_of,
                 Polygon_soup& soup)
    : texture_coordinates_(texture_coordinates), uv_of_(uv_of), soup_(soup)
  {}

  std::size_t point_with(std::size_t point, std::size_t uv)
  {
    std::vector<std::size_t>& copies = copies_[point];
    for(std::size_t copy : copies)
      if(same_uv(texture_coordinates_[uv_of_[copy] - 1], texture_coordinates_[uv - 1]))
        return copy;
    const std::size_t copy = soup_.points.size();
    soup_.points.push_back(soup_.points[point]);
    if(!soup_.colors.empty())
      soup_.colors.push_back(soup_.colors[point]);
    uv_of_.push_back(uv);
    copies.push_back(copy);
    ++soup_.uv_seam_copies;
    return copy;
  }

private:
  const std::vector<std::array<double, 2>>& texture_coordinates_;
  std::vector<std::size_t>& uv_of_;
  Polygon_soup& soup_;
  std::unordered_map<std::size_t, std::vector<std::size_t>> copies_; // by point with a seam
};

/// One UV per point from the corners' texture coordinates, into `soup.uvs`: kept only
/// if every corner has one, and each point only one (coinciding values count as one)
/// or `seams` is Uv_seams::SPLIT (a copy of the point per further one); otherwise the
/// points with several are counted in `soup.uv_seam_points` and the corners with none
/// in `soup.uv_missing_corners`.
inline void uvs_of_corners(const std::vector<std::array<double, 2>>& texture_coordinates,
                           const std::vector<std::vector<std::size_t>>& corner_uvs, Uv_seams seams,
                           Polygon_soup& soup)
{
  constexpr std::size_t none = 0;
  std::vector<std::size_t> uv_of(soup.points.size(), none);
  std::vector<std::uint8_t> on_seam(soup.points.size(), 0);
  Uv_seam_copies copies(texture_coordinates, uv_of, soup);
  std::size_t corners_without = 0;
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
    for(std::size_t c = 0; c < soup.polygons[f].size(); ++c) {
      const std::size_t point = soup.polygons[f][c], uv = corner_uvs[f][c];
      if(uv == none) {
        ++corners_without;
        continue;
      }
      if(uv_of[point] == none)
        uv_of[point] = uv;
      else if(!same_uv(texture_coordinates[uv_of[point] - 1], texture_coordinates[uv - 1])) {
        if(seams == Uv_seams::SPLIT)
          soup.polygons[f][c] = copies.point_with(point, uv);
        else
          on_seam[point] = 1;
      }
    }
  soup.uv_seam_points = std::size_t(std::count(on_seam.begin(), on_seam.end(), 1));
  const bool any_corner = std::any_of(uv_of.begin(), uv_of.end(), [](std::size_t uv) { return uv != none; });
  if(!any_corner) // `vt` lines no face uses: the file gives no vertex a UV
    return;
  soup.uv_missing_corners = corners_without;
  if(soup.uv_seam_points > 0 || corners_without > 0)
    return;
  soup.uvs.resize(soup.points.size(), {{0, 0}}); // a point of no face: unused
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    if(uv_of[i] != none)
      soup.uvs[i] = texture_coordinates[uv_of[i] - 1];
}

/// "v x y z [w | r g b]", "vt u v" and "f a b c ..." lines (a corner: "i", "i/t",
/// "i//n", "i/t/n"; negative indices count back from the last vertex or texture
/// coordinate); other lines ignored. The texture coordinates are kept where every
/// vertex has one (see `uvs_of_corners()`).
inline Polygon_soup read_obj(std::string_view text, const std::string& name, Uv_seams seams)
{
  auto fail = [&](std::size_t line, const std::string& what) -> void {
    throw Read_error(name + ": " + what + " (line " + std::to_string(line) + ")");
  };
  Text_cursor in(text);
  Polygon_soup soup;
  Color_channels colors;
  std::vector<std::array<double, 2>> texture_coordinates;
  std::vector<std::vector<std::size_t>> corner_uvs; // per polygon, per corner: a `vt`, or 0 for none
  std::size_t dangling_uvs = 0; // corners whose `vt` the file does not define
  std::size_t line = 1;
  // The next word of the statement: a line that ends in '\\' goes on on the next one
  // (the OBJ specification's continuation; some exporters break long faces so).
  auto word = [&]() -> std::string_view {
    for(;;) {
      std::string_view w = in.word_in_line('#');
      if(w.empty() || w.back() != '\\' || !in.at_line_end('#'))
        return w;
      in.next_line();
      ++line;
      w.remove_suffix(1);
      if(!w.empty())
        return w;
    }
  };
  auto end_statement = [&] { // past its last line, continuations included
    while(!word().empty()) {
    }
    in.next_line();
  };
  for(; !in.at_end(); ++line, end_statement()) {
    const std::string_view keyword = word();
    if(keyword == "vt") { // "vt u [v [w]]", v is 0 if absent
      std::array<double, 2> uv{};
      if(!to_double(word(), uv[0]))
        fail(line, "a texture coordinate has no number");
      const std::string_view v = word(), w = word();
      double depth = 0; // w, unused
      if((!v.empty() && !to_double(v, uv[1])) || (!w.empty() && !to_double(w, depth)))
        fail(line, "a texture coordinate is not a number");
      if(!std::isfinite(uv[0]) || !std::isfinite(uv[1]))
        fail(line, "a texture coordinate is not a finite number");
      texture_coordinates.push_back(uv);
      continue;
    }
    if(keyword == "v") {
      double x[7];
      int n = 0;
      for(std::string_view w; n < 7 && !(w = word()).empty(); ++n)
        if(!to_double(w, x[n]))
          fail(line, "a vertex has a coordinate that is not a number");
      if(n < 3)
        fail(line, "a vertex has fewer than 3 coordinates");
      soup.points.push_back({{x[0], x[1], x[2]}});
      if(n >= 6) { // x y z r g b, colours in [0, 1] (or 0..255: Color_channels)
        for(int c = 0; c < 3; ++c)
          if(!std::isfinite(x[3 + c]))
            fail(line, "a vertex colour is not a finite number");
        colors.add(soup.points.size() - 1, {{x[3], x[4], x[5]}}, Color_range::UNIT_OR_BYTE);
      }
    } else if(keyword == "f") {
      std::vector<std::size_t> polygon, uvs;
      for(std::string_view w; !(w = word()).empty();) {
        Obj_corner corner;
        if(!parse_obj_corner(w, corner))
          fail(line, "a face corner '" + std::string(w.substr(0, 40)) +
                         "' is not v, v/t, v//n or v/t/n with non-zero integers");
        const std::size_t v = resolved_obj_index(corner.v, soup.points.size()),
                          t = resolved_obj_index(corner.t, texture_coordinates.size());
        if(v == 0)
          fail(line, "a face refers to a vertex not defined before it");
        if(corner.t != 0 && t == 0)
          ++dangling_uvs;
        polygon.push_back(v - 1);
        uvs.push_back(t);
      }
      soup.polygons.push_back(std::move(polygon));
      corner_uvs.push_back(std::move(uvs));
    }
  }
  if(colors.any())
    soup.colors = colors.take(soup.points.size(), soup.notes);
  if(dangling_uvs > 0) // the faces are whole; which texture coordinates were meant is not known
    soup.notes.push_back(std::to_string(dangling_uvs) + " face corner" + (dangling_uvs == 1 ? " refers" : "s refer") +
                         " to a texture coordinate not defined before it: texture coordinates not read");
  else if(!texture_coordinates.empty())
    uvs_of_corners(texture_coordinates, corner_uvs, seams, soup);
  return soup;
}

// ------------------------------------------------------------------------ STL

/// `c` in lower case (ASCII letters only: not the locale's).
inline char lower_case(char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; }

/// `text` in lower case (ASCII letters only).
inline std::string lower_case(std::string_view text)
{
  std::string lower(text);
  for(char& c : lower)
    c = lower_case(c);
  return lower;
}

/// Whether `word` is `keyword` (lower case) in any case: STL's keywords are lower case,
/// some exporters write them in capitals.
inline bool is_keyword(std::string_view word, std::string_view keyword)
{
  return word.size() == keyword.size() &&
         std::equal(word.begin(), word.end(), keyword.begin(), [](char a, char b) { return lower_case(a) == b; });
}

/// Whether an STL file is binary: its size is that of its triangle count (some binary
/// files start with "solid" too), or its start is not text with STL's keywords, in any
/// case (some exporters write "beginsolid" or nothing before the first facet).
inline bool is_binary_stl(std::string_view text)
{
  if(text.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, text.data() + 80, 4);
    if(84 + 50 * std::uint64_t(count) == text.size())
      return true;
  }
  const std::string_view start = text.substr(0, 1024);
  if(start.find('\0') != std::string_view::npos)
    return true;
  Text_cursor in(text);
  const std::string first = lower_case(in.word()), lower_start = lower_case(start);
  return first.find("solid") == std::string::npos && first != "facet" &&
         lower_start.find("vertex") == std::string::npos;
}

/// The index of each distinct position: STL gives every triangle its own three points,
/// and, as every STL reader does, the points at the same position are one vertex.
class Stl_vertices
{
public:
  explicit Stl_vertices(std::vector<std::array<double, 3>>& points) : points_(points) {}
  std::size_t index_of(const std::array<double, 3>& p)
  {
    const auto [it, added] = index_.emplace(p, points_.size());
    if(added)
      points_.push_back(p);
    return it->second;
  }

private:
  std::vector<std::array<double, 3>>& points_;
  std::unordered_map<Position, std::size_t, Position_hash> index_;
};

/// How many triangles a binary STL file holds: the count in its header, unless the
/// records after it are a whole number of triangles, and another one (exporters that
/// stream their triangles leave 0 there); a note says which was taken, and how many
/// bytes after the triangles are left.
inline std::uint32_t binary_stl_triangles(std::string_view text, const std::string& name,
                                          std::vector<std::string>& notes)
{
  std::uint32_t count = 0;
  std::memcpy(&count, text.data() + 80, 4); // STL is little endian, as the hosts we build for
  const std::uint64_t records = (text.size() - 84) / 50, left = (text.size() - 84) % 50;
  if(records == 0 && count > 0) // nothing to read: say what the header promised
    throw Read_error(name + ": its binary STL header counts " + std::to_string(count) +
                     " triangles, and the file holds none");
  if(left == 0 && records != count && records <= UINT32_MAX) {
    notes.push_back("its binary STL header counts " + std::to_string(count) + " triangles, the file holds " +
                    std::to_string(records) + ": all " + std::to_string(records) + " are read");
    return std::uint32_t(records);
  }
  if(count > records)
    throw Read_error(name + ": its binary STL triangle count (" + std::to_string(count) + ") is larger than the file");
  if(84 + 50 * std::uint64_t(count) < text.size())
    notes.push_back("its " + std::to_string(text.size() - 84 - 50 * std::uint64_t(count)) +
                    " bytes after the " + std::to_string(count) + " triangles its binary STL header counts are ignored");
  return count;
}

/// The triangles of an STL file, their corners at the same position joined.
inline Polygon_soup read_stl(std::string_view text, const std::string& name)
{
  auto fail = [&](const std::string& what) -> void { throw Read_error(name + ": " + what); };
  Polygon_soup soup;
  Stl_vertices vertices(soup.points);
  if(is_binary_stl(text)) {
    if(text.size() < 84)
      fail("not an STL file (too short for a binary STL, and no 'solid' keyword)");
    const std::uint32_t count = binary_stl_triangles(text, name, soup.notes);
    soup.polygons.reserve(count);
    for(std::uint32_t t = 0; t < count; ++t) {
      const char* record = text.data() + 84 + 50 * std::size_t(t) + 12; // after the normal
      std::vector<std::size_t> triangle;
      for(int c = 0; c < 3; ++c) {
        float xyz[3];
        std::memcpy(xyz, record + 12 * c, 12);
        triangle.push_back(vertices.index_of({{double(xyz[0]), double(xyz[1]), double(xyz[2])}}));
      }
      soup.polygons.push_back(std::move(triangle));
    }
    return soup;
  }
  Text_cursor in(text);
  std::vector<std::size_t> loop;
  for(std::string_view w; !(w = in.word()).empty();) {
    if(is_keyword(w, "vertex")) {
      std::array<double, 3> p{};
      for(double& x : p)
        if(!to_double(in.word(), x))
          fail("an STL vertex has a coordinate that is not a number");
      if(loop.size() >= 3)
        fail("an STL facet has more than 3 vertices");
      loop.push_back(vertices.index_of(p));
    } else if(is_keyword(w, "endloop") || is_keyword(w, "endfacet")) {
      if(!loop.empty())
        soup.polygons.push_back(std::move(loop));
      loop.clear();
    }
  }
  if(!loop.empty())
    fail("its last STL facet is not closed (no endloop)");
  return soup;
}

// ------------------------------------------------------------------------ entry

/// The soup in `text`, a file of the format with extension `extension` (see
/// mesh_formats.h); `name` names it in messages. Throws Read_error.
inline Polygon_soup parse_mesh(std::string_view text, const std::string& extension, const std::string& name,
                               Uv_seams seams = Uv_seams::DROP)
{
  if(text.empty())
    throw Read_error(name + " is empty");
  const auto format = format_with_extension(extension);
  if(!format)
    throw Read_error(name + ": unsupported format (use " + supported_extensions() + ")");
  // a UTF-8 byte-order mark, which some Windows editors write before a text
  // file or a PLY header; not for STL, whose binary header may start with any bytes
  constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";
  if(format->format != Mesh_format::STL &&
     text.substr(0, byte_order_mark.size()) == byte_order_mark)
    text.remove_prefix(byte_order_mark.size());
  switch(format->format) {
  case Mesh_format::OFF: return read_off(text, name);
  case Mesh_format::PLY: return read_ply(text, name);
  case Mesh_format::OBJ: return read_obj(text, name, seams);
  case Mesh_format::STL: return read_stl(text, name);
  }
  throw Read_error(name + ": unsupported format"); // not reached: every format is above
}

} // namespace internal

/// The soup in the file `path`, its format chosen by its extension. Throws Read_error.
inline Polygon_soup read_mesh_file(const std::string& path, Uv_seams seams = Uv_seams::DROP)
{
  const internal::Mapped_file file(path);
  return internal::parse_mesh(file.text(), extension_of(path), "'" + path + "'", seams);
}

} // namespace rsr_io

#endif // RANGE_SPACE_REMESHING_TOOLS_MESH_FILE_READER_H
