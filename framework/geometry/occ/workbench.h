// The OpenCASCADE backend's public face: a set of named shapes that journal
// operations create and modify, and the conversion of the result into a
// kernel-independent geom::Model. No OCCT type appears in this header; the
// implementation (workbench.cpp and friends in this folder) is the only
// place in Cooperage that includes OCCT headers.
#pragma once

#include "framework/geometry/model.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cooperage::occ {

using geom::Vec3;

class SolidPieces;

struct BuildOptions {
  /// Fragment all solids so that touching volumes share one Surface and
  /// every shared curve exists once (the conformal-assembly step).
  bool imprint_merge = true;
};

/// Named shapes plus the modelling operations of the journal. Every method
/// throws cooperage::MeshingError naming the shape and the reason on failure
/// (GeometryError for kernel failures, InvalidInput for bad arguments,
/// FileNotFound / ParseError for imports). Names are unique; creating an
/// existing name is an error.
class Workbench {
 public:
  Workbench();
  ~Workbench();
  Workbench(const Workbench&) = delete;
  Workbench& operator=(const Workbench&) = delete;

  /// STEP (.step/.stp), IGES (.iges/.igs) or BREP (.brep); the file's length
  /// unit is kept (no conversion to mm). `heal` runs shape healing for small
  /// tolerance defects. The kernel reads the file in a child process with a
  /// processor-time and memory limit (30 s + 10 s per MB, or
  /// $COOPERAGE_CAD_TIMEOUT seconds; the wall clock only as a backstop at 4
  /// times that plus a minute): a crash or a hang there is a ParseError "<file>: the CAD
  /// kernel could not read it (...)". The child also builds and validates
  /// the model of the file's shape, so a fault there stays in the child too.
  void import_file(const std::string& name, const std::string& path, bool heal = true);

  /// Tells imports whether build_model will imprint and merge (default: it
  /// will). With true, an import merges its own solids in its child process,
  /// and build_model reuses that when the import is the only shape.
  void set_imprint_merge(bool merge);

  /// Work this process does while the next import's child reads its file
  /// (once, then forgotten): the caller's own preparation, overlapped with
  /// the child's reading, e.g. loading an export's library. Its exceptions
  /// come out of that import_file.
  void set_while_importing(std::function<void()> task);

  void brick(const std::string& name, const Vec3& origin, const Vec3& size);
  void cylinder(const std::string& name, const Vec3& base, const Vec3& axis, double radius,
                double height);
  void cone(const std::string& name, const Vec3& base, const Vec3& axis, double radius1,
            double radius2, double height);
  void sphere(const std::string& name, const Vec3& center, double radius);
  /// Ring torus about `axis` through `center`: 0 < minor < major.
  void torus(const std::string& name, const Vec3& center, const Vec3& axis, double major_radius,
             double minor_radius);
  /// Planar polygon profile (implicitly closed) with optional polygon holes,
  /// extruded along `direction` (its length is the extrusion distance).
  void prism(const std::string& name, const std::vector<Vec3>& profile,
             const std::vector<std::vector<Vec3>>& holes, const Vec3& direction);
  /// Planar polygon profile revolved about the axis through `origin` along
  /// `axis` by `angle_deg` degrees (360 for a full revolution).
  void revolve(const std::string& name, const std::vector<Vec3>& profile, const Vec3& origin,
               const Vec3& axis, double angle_deg);
  /// B-spline surface interpolating a grid of points (grid[i][j], at least
  /// 2 x 2, rows of equal length). thickness == 0 keeps it a single free face;
  /// otherwise the face is extruded by `thickness` along its mean normal into
  /// a solid (negative: the other way).
  void bspline_patch(const std::string& name, const std::vector<std::vector<Vec3>>& grid,
                     double thickness);

  /// Solid through planar sections, in order (a loft; OCCT ThruSections).
  /// [in] sections  2 or more sections; each is a closed planar polygon of
  ///                >= 3 points (closed implicitly, do not repeat the first
  ///                point) or a single point (an apex), which is allowed only
  ///                as the first or the last section. Consecutive sections
  ///                must not lie in one plane. Model units.
  /// [in] ruled     true: straight (ruled) side faces between consecutive
  ///                sections; point j of a polygon joins point j of the next,
  ///                so every polygon needs the same number of points and the
  ///                same winding. false: smooth faces through all sections
  ///                (OCCT matches the sections itself; counts may differ).
  /// Example: a twisted square prism (squares at z = 0, 1, 2, 3, each turned
  /// 15 degrees more), a frustum, a pyramid or a tetrahedron (triangle + apex).
  void loft(const std::string& name, const std::vector<std::vector<Vec3>>& sections,
            bool ruled = true);

  /// name = inputs[0] ∪ inputs[1] ∪ ...; inputs are consumed (removed).
  void fuse(const std::string& name, const std::vector<std::string>& inputs);
  /// name = inputs[0] − inputs[1] − ...; inputs are consumed.
  void cut(const std::string& name, const std::vector<std::string>& inputs);
  /// name = inputs[0] ∩ inputs[1] ∩ ...; inputs are consumed.
  void common(const std::string& name, const std::vector<std::string>& inputs);
  /// Split `shape` into the pieces on either side of a plane (the pieces
  /// stay one named shape holding several solids).
  void webcut(const std::string& shape, const Vec3& origin, const Vec3& normal);

  void translate(const std::string& shape, const Vec3& by);
  void rotate(const std::string& shape, const Vec3& origin, const Vec3& axis, double angle_deg);
  void scale(const std::string& shape, const Vec3& origin, double factor);

  /// Names of the current shapes, in creation order.
  std::vector<std::string> names() const;
  bool has(const std::string& name) const;

  /// Writes the named shapes (all when empty) to a STEP, IGES or BREP file,
  /// chosen by the extension, in the unit of the imported files (mm if none).
  void write(const std::string& path, const std::vector<std::string>& shapes = {}) const;

  /// The model of all current shapes: solids in creation order (then their
  /// order inside each shape), imprinted and merged when asked. The same
  /// operations always give the same ids.
  geom::Model build_model(const BuildOptions& options = {}) const;

  /// Opaque state (defined in detail.h, used by the backend's own files).
  struct Impl;

 private:
  friend class SolidPieces;  // solid_pieces.h reads the shapes
  std::unique_ptr<Impl> impl_;
};

/// Reads a CAD file into a model in one step (import + build_model).
geom::Model load_model(const std::string& path, const BuildOptions& options = {});

/// Silences OCCT's console output (banners, messenger printers); called by
/// every entry point of this backend, harmless to call again.
void silence_kernel_output();

}  // namespace cooperage::occ
