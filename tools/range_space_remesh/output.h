// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: OUTPUT and the --topology-report file. Their names are checked
// before any work (a known format, neither overwriting INPUT); the files are written
// by mesh_file_writer.h under temporary names and renamed into place together, so a
// failing or interrupted run writes nothing.

#ifndef RANGE_SPACE_REMESHING_TOOLS_OUTPUT_H
#define RANGE_SPACE_REMESHING_TOOLS_OUTPUT_H

#include "failure.h"
#include "mesh_file_reader.h"
#include "mesh_file_writer.h"
#include "mesh_types.h"
#include "options.h"
#include "progress.h"
#include "topology_report.h"

#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

namespace rsr_program {

/// CGAL's readers and writers explain failures on std::cerr; the program reports
/// them in its own single line instead, so silence std::cerr while they run.
class Silenced_cerr
{
public:
  Silenced_cerr() : saved_(std::cerr.rdbuf(nullptr)) {}
  ~Silenced_cerr() { std::cerr.rdbuf(saved_); }

private:
  std::streambuf* saved_;
};

inline bool is_supported_format(const std::string& path) { return rsr_io::format_of(path).has_value(); }


/// Whether two paths name the same file: the same name, the same canonical path (the
/// file may not exist yet), or the same existing file under another name (a hard link).
inline bool same_file(const std::string& a, const std::string& b)
{
  namespace fs = std::filesystem;
  std::error_code a_error, b_error, equivalent_error;
  const fs::path canonical_a = fs::weakly_canonical(fs::absolute(a, a_error), a_error);
  const fs::path canonical_b = fs::weakly_canonical(fs::absolute(b, b_error), b_error);
  return a == b || (!a_error && !b_error && canonical_a == canonical_b) || fs::equivalent(a, b, equivalent_error);
}

/// Refuses an OUTPUT that would overwrite INPUT (the input would be lost for a remesh
/// of it), and a report that would overwrite INPUT or OUTPUT.
inline void check_output_paths(const Options& options)
{
  if(same_file(options.output, options.input))
    fail("OUTPUT " + quote(options.output) + " would overwrite INPUT; write the remesh to another file");
  if(options.topology_report.empty())
    return;
  for(const bool input : {true, false})
    if(same_file(options.topology_report, input ? options.input : options.output))
      fail("--topology-report " + quote(options.topology_report) + " would overwrite " +
           (input ? "INPUT " + quote(options.input) : "OUTPUT " + quote(options.output)));
}

/// Refuses, before any work, an OUTPUT or report of an unknown format and one that
/// would overwrite another file of the run.
inline void check_output_names(const Options& options)
{
  if(!is_supported_format(options.output))
    fail("cannot write " + quote(options.output) + ": unsupported format (use " + rsr_io::supported_extensions() + ")");
  if(!options.topology_report.empty() && !is_supported_format(options.topology_report))
    fail("cannot write " + quote(options.topology_report) + ": unsupported format (use " + rsr_io::supported_extensions() + ")");
  check_output_paths(options);
  try { // a device or a directory at a name (or where its link points) is not replaced
    rsr_io::internal::destination_of(options.output);
    if(!options.topology_report.empty())
      rsr_io::internal::destination_of(options.topology_report);
  } catch(const rsr_io::Write_error& e) {
    fail(e.what());
  }
}

/// Writes OUTPUT (with its vertex colours and texture coordinates) and the --topology-report file: every file
/// under a temporary name first, then all are renamed.
inline void write_outputs(const Options& options, const Mesh& input, const Mesh& output,
                          const std::vector<RSR::Topology_defect<Mesh::Face_index>>& defects)
{
  rsr_io::Output_files files;
  const rsr_io::Write_options write_options{options.binary, 17};
  try {
    Silenced_cerr silence; // CGAL's writers explain failures on std::cerr
    const auto colors = find_vertex_colors(output);
    const auto uvs = find_vertex_uvs(output);
    files.add(output, options.output, colors ? &*colors : nullptr, write_options, uvs ? &*uvs : nullptr);
    if(!options.topology_report.empty())
      files.add(flagged_faces(input, defects), options.topology_report, static_cast<const Color_map*>(nullptr),
                write_options);
    stop_if_interrupted(); // a Ctrl-C from here on comes too late: the files are written
    committing = 1;
    files.commit();
  } catch(const rsr_io::Write_error& e) {
    fail(e.what());
  }
}

/// One line on stderr when OUTPUT's format cannot hold the input's vertex values (STL
/// holds neither colours nor texture coordinates, OFF no texture coordinates): they
/// are not written, and nothing is lost without a word.
inline void report_unwritten_values(const Options& options, const Mesh& input)
{
  const auto format = rsr_io::format_of(options.output); // checked before any work
  std::string unwritten;
  if(find_vertex_colors(input) && !format->stores_colors)
    unwritten = "vertex colours";
  if(find_vertex_uvs(input) && !format->stores_uvs)
    unwritten += std::string(unwritten.empty() ? "" : " and ") + "texture coordinates";
  if(!unwritten.empty())
    std::cerr << "range_space_remesh: " << quote(options.output) << ": the input's " << unwritten
              << " are not written: ." << format->extension << " files do not hold them" << std::endl;
}

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_OUTPUT_H
