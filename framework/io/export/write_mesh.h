// write_mesh: export a MeshDB to the format named by the file extension;
// ExportBatch: the exports of one run, all or nothing.
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/export/export_options.h"
#include "framework/mesh/mesh_db.h"

#include <string>
#include <vector>

namespace cooperage::io {

/// Writes `db` to `path`, choosing the format by the (case-insensitive)
/// extension: .exo/.e/.g Exodus II (exodus_writer.h), .msh Gmsh 4.1 ASCII
/// (msh_writer.h), .vtu VTK XML unstructured grid (vtu_writer.h), .inp Abaqus
/// (inp_writer.h), .obj .off .stl .ply surface meshes through OpenMesh
/// (surface_writer.h: a volume mesh gives its boundary).
///
/// Every writer validates the mesh first (node indices in range, meshed ids
/// in the model; MeshingError(InvalidInput) otherwise), writes a temporary
/// file with an unpredictable name in the same directory, created
/// exclusively, and renames it to `path` on success. On failure the
/// temporary file is removed and MeshingError is thrown (FileNotFound for an
/// unwritable path), so an existing file at `path` is never replaced by a
/// partial one.
/// @param[in] path    output file
/// @param[in] db      the mesh (0-based node indices)
/// @param[in] model   the model the mesh belongs to (ids, names, topology)
/// @param[in] options see ExportOptions
/// @throws MeshingError(InvalidInput) for an unknown extension (the message
///         lists the allowed ones) or an invalid mesh.
void write_mesh(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
                const ExportOptions& options = {});

/// True when write_mesh knows the extension of `path` (.exo .e .g .msh .vtu .inp
/// .obj .off .stl .ply).
bool known_mesh_extension(const std::string& path);

/// Loads what writing `path` will need and is slow to load (the Exodus II
/// library for .exo .e .g), so that a later write does not wait for it, e.g.
/// from a thread beside the meshing. Thread-safe; does nothing for other
/// formats; a failure is left for the write to report.
void prepare_export(const std::string& path) noexcept;

/// Checks, before any meshing, that `path` can be written: a known
/// extension, an existing directory we may create files in (tried by
/// creating and removing a private directory there), and no directory at
/// `path` itself. Throws MeshingError(FileNotFound or InvalidInput) whose
/// message is one clause ("the directory \"out\" does not exist"); the
/// caller adds where the export was asked for.
void check_export_target(const std::string& path);

/// The exports of one run, all or nothing (issue 21 item 3). stage() writes
/// each mesh into a private directory (mkdtemp: mode 0700, unpredictable
/// name) inside its target's directory, so no other user can plant a link
/// where a writer opens files; commit() renames every staged file onto its
/// target. If a stage fails, or the batch is destroyed uncommitted, every
/// staged file and private directory is removed; if a rename fails, the
/// targets already renamed by this batch are removed too, so a run leaves
/// either all of its files or none.
class ExportBatch {
 public:
  ExportBatch() = default;
  ~ExportBatch();
  ExportBatch(const ExportBatch&) = delete;
  ExportBatch& operator=(const ExportBatch&) = delete;

  /// Writes `db` for `path` (format by extension, as write_mesh) into a
  /// private directory next to it. Throws MeshingError as write_mesh.
  void stage(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
             const ExportOptions& options = {});
  /// Renames every staged file onto its target, in stage order; returns the
  /// targets. Throws MeshingError(FileNotFound) after undoing the batch.
  std::vector<std::string> commit();

 private:
  struct Staged {
    std::string target;
    std::string dir;   ///< the private directory
    std::string file;  ///< the finished file inside it
  };
  void discard() noexcept;
  std::vector<Staged> staged_;
};

}  // namespace cooperage::io
