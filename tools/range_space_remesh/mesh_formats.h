// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The program's file formats, in one table: the reader, the writer, the check of
// OUTPUT's name and the messages all ask it.

#ifndef RANGE_SPACE_REMESHING_TOOLS_MESH_FORMATS_H
#define RANGE_SPACE_REMESHING_TOOLS_MESH_FORMATS_H

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <string>

namespace rsr_io {

enum class Mesh_format { OFF, OBJ, PLY, STL };

struct Mesh_format_entry
{
  Mesh_format format;
  const char* extension;   // lower case, without the dot
  bool has_binary;         // --ascii chooses text; OFF and OBJ are always text
  bool stores_colors;      // vertex colours
  bool stores_uvs;         // vertex texture coordinates
  bool stores_polygons;    // STL stores triangles only
};

inline constexpr std::array<Mesh_format_entry, 4> mesh_formats = {{
    {Mesh_format::OFF, "off", false, true, false, true},
    {Mesh_format::OBJ, "obj", false, true, true, true},
    {Mesh_format::PLY, "ply", true, true, true, true},
    {Mesh_format::STL, "stl", true, false, false, false},
}};

/// The extension of `path`, in lower case, without the dot ("" if none).
inline std::string extension_of(const std::string& path)
{
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  std::string ext = path.substr(dot + 1);
  for(char& c : ext)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

/// The entry of the format with extension `extension`, if the program has it.
inline std::optional<Mesh_format_entry> format_with_extension(const std::string& extension)
{
  const auto found = std::find_if(mesh_formats.begin(), mesh_formats.end(),
                                  [&](const Mesh_format_entry& e) { return extension == e.extension; });
  if(found == mesh_formats.end())
    return std::nullopt;
  return *found;
}

/// The entry of the format of `path`, by its extension.
inline std::optional<Mesh_format_entry> format_of(const std::string& path)
{
  return format_with_extension(extension_of(path));
}

/// ".off .obj .ply .stl", for messages.
inline std::string supported_extensions()
{
  std::string list;
  for(const Mesh_format_entry& e : mesh_formats)
    list += (list.empty() ? "." : " .") + std::string(e.extension);
  return list;
}

} // namespace rsr_io

#endif // RANGE_SPACE_REMESHING_TOOLS_MESH_FORMATS_H
