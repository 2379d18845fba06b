// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command-line program's writer: a mesh goes to a new temporary file next to
// its destination (created exclusively: an existing file or a link planted at its
// name is never followed), and every file of a run is renamed into place only once
// all of them are written, so that a failing run creates and overwrites nothing.
// The temporary files are removed on every error path and on the signals that end the program.

#ifndef RANGE_SPACE_REMESHING_TOOLS_MESH_FILE_WRITER_H
#define RANGE_SPACE_REMESHING_TOOLS_MESH_FILE_WRITER_H

#include "mesh_formats.h"

#include <CGAL/IO/Color.h>
#include <CGAL/Range_space_remeshing/internal/Polygon_splitting.h>
#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/PLY.h>
#include <CGAL/boost/graph/IO/STL.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <ext/stdio_filebuf.h> // an ostream on the file descriptor mkstemp gives
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rsr_io {

/// Why a file cannot be written, in one line.
struct Write_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

namespace internal {

/// The temporary files not yet renamed, for the signal handler: fixed storage,
/// as a handler may not allocate.
struct Pending_files
{
  static constexpr int capacity = 4;
  static constexpr std::size_t path_size = 4096;
  char paths[capacity][path_size];
  volatile std::sig_atomic_t used[capacity];
};

inline Pending_files& pending_files()
{
  static Pending_files files{};
  return files;
}

/// Whether a write has temporary files not yet renamed (safe in a signal handler).
inline bool has_pending_files()
{
  const Pending_files& files = pending_files();
  for(int i = 0; i < Pending_files::capacity; ++i)
    if(files.used[i])
      return true;
  return false;
}

/// Removes the temporary files not yet renamed (async-signal-safe).
inline void remove_pending_files()
{
  Pending_files& files = pending_files();
  for(int i = 0; i < Pending_files::capacity; ++i)
    if(files.used[i]) {
      ::unlink(files.paths[i]);
      files.used[i] = 0;
    }
}

/// The signals whose default action ends the program, which would leave the
/// temporary files behind (SIGXFSZ: the file size limit, met while writing).
inline constexpr int terminating_signals[] = {SIGINT,  SIGTERM,   SIGHUP,  SIGQUIT,   SIGPIPE, SIGXFSZ,
                                              SIGXCPU, SIGALRM,   SIGUSR1, SIGUSR2,   SIGVTALRM, SIGPROF};

extern "C" inline void remove_pending_files_and_die(int signal_number)
{
  remove_pending_files();
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

/// Holds the terminating signals for its lifetime: a signal that arrives meanwhile
/// is handled after, so that a temporary file is never created unregistered and a set
/// of files is renamed all or none.
class Signals_held
{
public:
  Signals_held()
  {
    sigset_t held;
    sigemptyset(&held);
    for(int s : terminating_signals)
      sigaddset(&held, s);
    ::pthread_sigmask(SIG_BLOCK, &held, &before_); // the thread that writes (the program has one)
  }
  Signals_held(const Signals_held&) = delete;
  Signals_held& operator=(const Signals_held&) = delete;
  ~Signals_held() { ::pthread_sigmask(SIG_SETMASK, &before_, nullptr); }

private:
  sigset_t before_;
};

/// The permissions a new file gets from this process' umask (mkstemp gives 0600).
inline mode_t new_file_mode()
{
  static const mode_t mode = [] {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return mode_t(0666 & ~mask);
  }();
  return mode;
}

/// The points of `mesh` (a `Surface_mesh`) and its faces split into triangles, as a soup (STL stores
/// triangles only), by the split the input gets (`prepare_input()`): a non-convex
/// face by a triangulation inside it, where a fan would fold over its reflex corners.
template <class Mesh>
void triangle_soup_of(const Mesh& mesh, std::vector<typename Mesh::Point>& points,
                      std::vector<std::vector<std::size_t>>& triangles)
{
  std::vector<std::size_t> position(mesh.num_vertices()); // by index, removed vertices included
  points.clear();
  for(auto v : vertices(mesh)) {
    position[v.idx()] = points.size();
    points.push_back(mesh.point(v));
  }
  triangles.clear();
  for(auto f : faces(mesh)) {
    triangles.emplace_back();
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      triangles.back().push_back(position[v.idx()]);
  }
  CGAL::Range_space_remeshing::internal::split_polygons(points, triangles);
}

/// Writes `mesh` as STL, its faces split into triangles (see above).
template <class Mesh, class NamedParameters>
bool write_triangles_STL(std::ostream& out, const Mesh& mesh, const NamedParameters& np)
{
  std::vector<typename Mesh::Point> points;
  std::vector<std::vector<std::size_t>> triangles;
  triangle_soup_of(mesh, points, triangles);
  return CGAL::IO::write_STL(out, points, triangles, np);
}

/// How many vertices of `mesh` sit where another one does once their coordinates
/// are written as `Scalar`s.
template <class Scalar, class Mesh>
std::size_t coinciding_vertices(const Mesh& mesh)
{
  std::vector<std::array<Scalar, 3>> positions;
  positions.reserve(num_vertices(mesh));
  for(auto v : vertices(mesh)) {
    const auto p = get(CGAL::vertex_point, mesh, v);
    positions.push_back({{static_cast<Scalar>(CGAL::to_double(p.x())), static_cast<Scalar>(CGAL::to_double(p.y())),
                          static_cast<Scalar>(CGAL::to_double(p.z()))}});
  }
  std::sort(positions.begin(), positions.end());
  const auto distinct = std::unique(positions.begin(), positions.end());
  return std::size_t(positions.end() - distinct);
}

/// How many vertices of `mesh` sit where another one does once written to STL (as
/// floats in binary, as doubles in text): STL stores positions only, so a reader
/// would join them, and the file would not be the same surface.
template <class Mesh>
std::size_t vertices_joined_by_stl(const Mesh& mesh, bool binary)
{
  return binary ? coinciding_vertices<float>(mesh) : coinciding_vertices<double>(mesh);
}

} // namespace internal

/// Removes the temporary files of unfinished writes when a signal ends the program
/// (internal::terminating_signals, those not ignored), then dies of the signal as it
/// would have.
inline void remove_temporary_files_on_signals()
{
  internal::pending_files();
  internal::new_file_mode();
  for(int s : internal::terminating_signals) {
    struct sigaction current;
    if(::sigaction(s, nullptr, &current) == 0 && current.sa_handler == SIG_IGN)
      continue; // ignored by who started the program (SIGPIPE, SIGHUP under nohup): kept so
    std::signal(s, internal::remove_pending_files_and_die);
  }
}

/// How a mesh is written.
struct Write_options
{
  bool binary = true; // PLY and STL; OFF and OBJ are text
  int precision = 17; // digits of text coordinates: doubles read back exactly
};

namespace internal {

/// The type of "no texture coordinates" (a null `uvs`).
struct No_uvs
{};

/// OBJ with vertex colours or texture coordinates, which CGAL's writer leaves out:
/// colours as "v x y z r g b", r g b in [0, 1] (the extension MeshLab and Blender
/// read, and the program's reader), texture coordinates as "vt" lines and faces
/// "f a/a b/b ...", one UV per vertex.
template <class Mesh, class ColorMap, class UVMap>
bool write_obj_with_values(std::ostream& out, const Mesh& mesh, const ColorMap* colors, const UVMap* uvs,
                           int precision)
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  std::map<vertex_descriptor, std::size_t> index;
  out << std::setprecision(precision);
  for(vertex_descriptor v : vertices(mesh)) {
    index.emplace(v, index.size() + 1);
    const auto& p = get(CGAL::vertex_point, mesh, v);
    out << "v " << p.x() << ' ' << p.y() << ' ' << p.z();
    if(colors) {
      const auto& c = get(*colors, v);
      out << std::setprecision(6) << ' ' << c.red() / 255. << ' ' << c.green() / 255. << ' ' << c.blue() / 255.
          << std::setprecision(precision); // six digits give each of the 256 levels back
    }
    out << '\n';
  }
  bool with_uvs = false;
  if constexpr(!std::is_same<UVMap, No_uvs>::value)
    if(uvs) {
      with_uvs = true;
      for(vertex_descriptor v : vertices(mesh))
        out << "vt " << get(*uvs, v).x() << ' ' << get(*uvs, v).y() << '\n';
    }
  for(auto f : faces(mesh)) {
    out << 'f';
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) {
      out << ' ' << index[v];
      if(with_uvs)
        out << '/' << index[v];
    }
    out << '\n';
  }
  return out.good();
}

/// A copy of `mesh` with its texture coordinates as the vertex properties "v:s" and
/// "v:t" of doubles, which CGAL's PLY writer writes as the properties s and t.
template <class Mesh, class UVMap>
Mesh with_st_properties(const Mesh& mesh, const UVMap& uvs)
{
  Mesh copy = mesh;
  auto s = copy.template add_property_map<typename Mesh::Vertex_index, double>("v:s").first;
  auto t = copy.template add_property_map<typename Mesh::Vertex_index, double>("v:t").first;
  for(auto v : vertices(copy)) { // a copy keeps the indices
    s[v] = get(uvs, v).x();
    t[v] = get(uvs, v).y();
  }
  return copy;
}

} // namespace internal

/// Writes `mesh` to `out` in the format with extension `ext` (see mesh_formats.h),
/// with the vertex colours `colors` (if not null) where the format stores them (OFF,
/// PLY) and the texture coordinates `uvs` (if not null) where it stores them (PLY as s
/// and t, OBJ as vt); faces are split into triangles for STL. False on a stream error
/// or an unknown format.
template <class Mesh, class ColorMap, class UVMap = internal::No_uvs>
bool write_mesh(std::ostream& out, const Mesh& mesh, const std::string& ext, const ColorMap* colors,
                const Write_options& options, const UVMap* uvs = nullptr)
{
  const auto format = format_with_extension(ext);
  if(!format)
    return false;
  const auto precision = CGAL::parameters::stream_precision(options.precision);
  CGAL::IO::set_mode(out, options.binary && format->has_binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
  if(!format->stores_colors)
    colors = nullptr;
  if constexpr(!std::is_same<UVMap, internal::No_uvs>::value) {
    if(uvs && format->stores_uvs)
      return format->format == Mesh_format::OBJ
                 ? internal::write_obj_with_values(out, mesh, colors, uvs, options.precision)
                 : write_mesh(out, internal::with_st_properties(mesh, *uvs), ext, colors, options); // PLY: s t
  }
  switch(format->format) {
  case Mesh_format::STL: return internal::write_triangles_STL(out, mesh, precision);
  case Mesh_format::OBJ:
    return colors ? internal::write_obj_with_values(out, mesh, colors, static_cast<const internal::No_uvs*>(nullptr),
                                                    options.precision)
                  : CGAL::IO::write_OBJ(out, mesh, precision);
  case Mesh_format::OFF:
    return colors ? CGAL::IO::write_OFF(out, mesh, precision.vertex_color_map(*colors))
                  : CGAL::IO::write_OFF(out, mesh, precision);
  case Mesh_format::PLY:
    return colors ? CGAL::IO::write_PLY(out, mesh, "", precision.vertex_color_map(*colors))
                  : CGAL::IO::write_PLY(out, mesh, "", precision);
  }
  return false; // not reached: every format is above
}

namespace internal {

/// The file writing `path` replaces: the file a symbolic link names (as a shell's
/// redirection writes through it; replaced, the link would be gone and the file it
/// names unchanged) or `path` itself. Throws Write_error if that is something other
/// than a regular file (a directory, a device, a pipe), which a rename would replace.
inline std::string destination_of(const std::string& path)
{
  namespace fs = std::filesystem;
  std::error_code error;
  std::string destination = path;
  if(fs::is_symlink(fs::symlink_status(path, error))) {
    const fs::path target = fs::weakly_canonical(fs::absolute(path, error), error);
    if(!error)
      destination = target.string();
  }
  const fs::file_status status = fs::status(destination, error);
  if(fs::exists(status) && !fs::is_regular_file(status))
    throw Write_error("cannot write '" + path + "': it is not a regular file" +
                      (destination == path ? std::string() : " ('" + destination + "')"));
  return destination;
}

} // namespace internal

/// The files a run writes, each first under a temporary name; `commit()` renames
/// them all into place, the destructor removes those not committed.
class Output_files
{
public:
  Output_files() = default;
  Output_files(const Output_files&) = delete;
  Output_files& operator=(const Output_files&) = delete;
  ~Output_files() { discard(); }

  /// Writes `mesh` (with the vertex colours `colors` and texture coordinates `uvs`, if
  /// not null, where the format stores them; see `write_mesh()`) for `path`, under a
  /// temporary name next to it.
  template <class Mesh, class ColorMap, class UVMap = internal::No_uvs>
  void add(const Mesh& mesh, const std::string& path, const ColorMap* colors, const Write_options& options,
           const UVMap* uvs = nullptr)
  {
    const std::string ext = extension_of(path);
    const auto format = format_with_extension(ext);
    if(!format)
      throw Write_error("cannot write '" + path + "': unsupported format (use " + supported_extensions() + ")");
    if(!format->stores_polygons)
      if(const std::size_t joined = internal::vertices_joined_by_stl(mesh, options.binary))
        throw Write_error("cannot write '" + path + "': " + std::to_string(joined) +
                          (joined == 1 ? " vertex of the mesh would coincide with another"
                                       : " vertices of the mesh would coincide with others") +
                          " in STL, which stores positions only" +
                          (options.binary ? " (as floats)" : "") + "; write .off, .ply or .obj");
    const std::string destination = internal::destination_of(path);
    int slot = -1;
    internal::Pending_files& pending = internal::pending_files();
    for(int i = 0; i < internal::Pending_files::capacity && slot < 0; ++i)
      if(!pending.used[i])
        slot = i;
    const auto slash = destination.find_last_of('/');
    // short, whatever the destination's name: a name of 255 bytes stays writable
    const std::string temporary =
        (slash == std::string::npos ? "" : destination.substr(0, slash + 1)) + ".rsr-XXXXXX";
    if(slot < 0 || temporary.size() >= internal::Pending_files::path_size)
      throw Write_error("cannot write '" + path + "': path too long");
    std::vector<char> name(temporary.begin(), temporary.end());
    name.push_back('\0');
    files_.reserve(files_.size() + 1);
    int fd;
    {
      internal::Signals_held held; // created and registered at once
      fd = ::mkstemp(name.data()); // O_CREAT | O_EXCL: never an existing file or link
      if(fd < 0)
        throw Write_error("cannot write '" + path + "': " + std::strerror(errno));
      std::memcpy(pending.paths[slot], name.data(), name.size());
      pending.used[slot] = 1;
      files_.push_back({std::string(name.data()), destination, path, slot});
    }
    ::fchmod(fd, internal::new_file_mode());
    bool ok = false;
    {
      __gnu_cxx::stdio_filebuf<char> buffer(fd, std::ios::out | std::ios::binary); // closes fd
      std::ostream out(&buffer);
      try {
        ok = write_mesh(out, mesh, ext, colors, options, uvs) && out.flush().good();
      } catch(const std::exception&) {
        ok = false;
      }
      ok = buffer.close() != nullptr && ok;
    }
    if(!ok)
      throw Write_error("cannot write '" + path + "' (disk full or not writable?)");
  }

  /// Renames every file into place; a signal meanwhile is handled after the renames.
  void commit()
  {
    internal::Signals_held held;
    for(File& f : files_) {
      if(std::rename(f.temporary.c_str(), f.destination.c_str()) != 0)
        throw Write_error("cannot write '" + f.path + "': " + std::strerror(errno));
      internal::pending_files().used[f.slot] = 0;
      f.temporary.clear();
    }
    files_.clear();
  }

  /// Removes the files not renamed.
  void discard()
  {
    for(File& f : files_)
      if(!f.temporary.empty()) {
        internal::pending_files().used[f.slot] = 0;
        std::remove(f.temporary.c_str());
      }
    files_.clear();
  }

private:
  struct File
  {
    std::string temporary, destination, path; // path: as the user named it
    int slot;
  };

  std::vector<File> files_;
};

} // namespace rsr_io

#endif // RANGE_SPACE_REMESHING_TOOLS_MESH_FILE_WRITER_H
