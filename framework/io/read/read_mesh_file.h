// read_mesh_file: read the elements of an existing mesh file (.exo, .msh,
// .vtu written by Cooperage or by other tools) for the quality report.
#pragma once

#include "framework/quality/metric.h"

#include <Eigen/Core>

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace cooperage::io {

/// The elements of one type in one block of a mesh file.
struct MeshBlock {
  std::string name;  ///< Exodus block name, Gmsh physical name, "<dim>:<tag>", ...
  quality::ElementType type = quality::ElementType::Hex;
  /// Flat, 0-based indices into MeshFile::coords; node_count(type) per
  /// element, in Exodus/VTK linear node order (quality/metric.h).
  std::vector<int> connectivity;
  /// Number of elements (connectivity.size() / node_count(type)).
  std::size_t size() const {
    return connectivity.size() / static_cast<std::size_t>(quality::node_count(type));
  }
};

/// The nodes and the tri / quad / wedge / hex elements of a mesh file.
struct MeshFile {
  std::vector<Eigen::Vector3d> coords;  ///< node coordinates; z = 0 for 2D files
  std::vector<MeshBlock> blocks;        ///< in file order; blocks are never empty
  /// Cells of other types (lines, vertices, tets, pyramids, higher order)
  /// that were skipped, counted by a type name of the format ("tetra4",
  /// "gmsh type 4", "vtk type 10", "TETRA").
  std::map<std::string, std::size_t> skipped;
};

/// Reads `path`, choosing the format by the (case-insensitive) extension:
///  - .exo .e .g: Exodus II through libexodus; element blocks of type HEX
///    (HEX8), WEDGE (WEDGE6), QUAD (QUAD4, SHELL4), TRI (TRI3, TRIANGLE,
///    SHELL3); one MeshBlock per element block, named by its Exodus name or
///    "block <id>"; 2D files get z = 0.
///  - .msh: Gmsh 4.1 or 2.2 ASCII; element types 2 tri, 3 quad, 5 hex,
///    6 prism; one MeshBlock per (entity, type), named by the entity's first
///    physical name or "<dim>:<tag>" (2.2: the physical name of the first
///    tag, else "<dim>:<elementary tag>").
///  - .vtu: VTK XML UnstructuredGrid, DataArrays in "ascii" or uncompressed
///    base64 "binary" format (UInt32 / UInt64 header); VTK types 5, 9, 12,
///    13 (wedges converted to Exodus order); one MeshBlock per (block_id cell
///    value, type) when a "block_id" cell array exists, else per type.
/// @param[in] path the file
/// @throws MeshingError(FileNotFound) "<path>: no such file";
///         MeshingError(ParseError) "<path>: <reason>" (with "line N" where
///         the format is line based); MeshingError(NotSupported) for binary
///         .msh, appended or compressed .vtu data; MeshingError(InvalidInput)
///         for an unknown extension (the message lists the allowed ones).
MeshFile read_mesh_file(const std::string& path);

}  // namespace cooperage::io
