// A typed journal: everything a `cooperage run` needs, read from XML by
// read_journal() (journal_reader.h). Plain data; no behaviour.
// The format is documented in docs/journal.md and docs/cooperage-journal.xsd.
#pragma once

#include "framework/geometry/types.h"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace cooperage::io {

using geom::Vec3;

/// Where a journal element came from, for error messages.
struct SourceLocation {
  std::string file;
  int line = 0;
  std::string element;  ///< XML element name
};

// ---- geometry operations, executed in journal order -----------------------

/// Import a CAD file (.step/.stp, .iges/.igs, .brep) as shape `name`.
struct ImportOp {
  std::string name;
  std::string file;
  bool heal = true;
};
/// Axis-aligned box from `origin` with edge lengths `size`.
struct BrickOp {
  std::string name;
  Vec3 origin = Vec3::Zero();
  Vec3 size = Vec3::Ones();
};
struct CylinderOp {
  std::string name;
  Vec3 base = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double radius = 1;
  double height = 1;
};
struct ConeOp {
  std::string name;
  Vec3 base = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double radius1 = 1;
  double radius2 = 0;
  double height = 1;
};
struct SphereOp {
  std::string name;
  Vec3 center = Vec3::Zero();
  double radius = 1;
};
/// A ring torus: the tube's centre circle (major radius) about `axis`
/// through `center`; minor_radius < major_radius.
struct TorusOp {
  std::string name;
  Vec3 center = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double major_radius = 2;
  double minor_radius = 1;
};
/// A planar polygon (closed implicitly), e.g. a profile or a hole.
using Polygon = std::vector<Vec3>;
/// Planar profile (with optional hole profiles) extruded along `direction`.
struct PrismOp {
  std::string name;
  Polygon profile;
  std::vector<Polygon> holes;
  Vec3 direction;
};
/// Planar profile revolved about the axis through `origin` along `axis` by `angle` degrees.
struct RevolveOp {
  std::string name;
  Polygon profile;
  Vec3 origin = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double angle = 360;
};
/// Solid through planar sections in order (a loft). Each section is a planar
/// polygon (>= 3 points) or, first or last only, a single point (an apex).
/// ruled: straight side faces, point j joined to point j of the next section
/// (every polygon has the same number of points); otherwise smooth faces.
struct LoftOp {
  std::string name;
  std::vector<Polygon> sections;
  bool ruled = true;
};
enum class BooleanKind { Fuse, Cut, Common };
/// `name` = inputs[0] op inputs[1] op ...; the inputs are consumed.
struct BooleanOp {
  std::string name;
  BooleanKind kind = BooleanKind::Fuse;
  std::vector<std::string> inputs;
};
struct TranslateOp {
  std::string shape;
  Vec3 by = Vec3::Zero();
};
/// Rotation about the axis through `origin` along `axis` by `angle` degrees.
struct RotateOp {
  std::string shape;
  Vec3 origin = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double angle = 0;
};
struct ScaleOp {
  std::string shape;
  Vec3 origin = Vec3::Zero();
  double factor = 1;
};
/// Split a shape by the plane through `origin` with normal `normal` (webcut).
struct WebcutOp {
  std::string shape;
  Vec3 origin = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
};

using GeometryOp =
    std::variant<ImportOp, BrickOp, CylinderOp, ConeOp, SphereOp, TorusOp, PrismOp, RevolveOp,
                 LoftOp, BooleanOp, TranslateOp, RotateOp, ScaleOp, WebcutOp>;

struct GeometryStep {
  GeometryOp op;
  SourceLocation where;
};

// ---- meshing settings ------------------------------------------------------

enum class Firmness { Default, Soft, Hard };
enum class BiasKind { None, Geometric, Dual };

/// Sizing and scheme settings for one entity (or the global default when
/// id == 0 in MeshSettings::global).
struct SizeSetting {
  std::optional<double> size;    ///< target element size
  std::optional<int> intervals;  ///< interval count (curves)
  Firmness firmness = Firmness::Default;
};

struct CurveSetting {
  int id = 0;
  SizeSetting sizing;
  BiasKind bias = BiasKind::None;
  std::optional<double> bias_ratio;       ///< growth ratio between neighbours
  std::optional<double> bias_first_size;  ///< first element size (instead of ratio)
  bool reverse_bias = false;              ///< bias from the end vertex
  SourceLocation where;
};

enum class ElementKind { Hex, Wedge, Mixed };

struct SurfaceSetting {
  int id = 0;
  SizeSetting sizing;
  /// "auto" or a registered surface scheme's name ("map", "submap", "pave",
  /// "tri", "quad_dominant", a plug-in's); checked against the registry
  /// when the run starts (pipeline/check_settings.h).
  std::string scheme = "auto";
  SourceLocation where;
};

struct VolumeSetting {
  int id = 0;
  SizeSetting sizing;
  std::string scheme = "auto";  ///< "auto" or a registered volume scheme ("map", "cooper", ...)
  /// This volume's element kind over <mesh elements>; unset: the mesh's.
  std::optional<ElementKind> elements;
  std::vector<int> sources;       ///< sweep source surface hints
  std::vector<int> targets;       ///< sweep target surface hints
  std::optional<Vec3> direction;  ///< sweep direction hint
  SourceLocation where;
};

enum class VertexType { End, Side, Corner, Reversal };
/// A hard vertex classification on a surface (submap).
struct VertexTypeSetting {
  int surface = 0;
  int vertex = 0;
  VertexType type = VertexType::End;
  SourceLocation where;
};

/// <mesh decompose="auto|off">: cut volumes no volume scheme applies to
/// into pieces one does (framework/decompose/decompose.h).
enum class Decompose { Auto, Off };

struct MeshSettings {
  std::optional<double> size;  ///< global element size
  /// "D/N" (io/element_size.h): the size is the model's bounding-box
  /// diagonal over this; pipeline::resolve_relative_size turns it into
  /// `size` once the model is built.
  std::optional<double> size_divisor;
  int threads = 0;             ///< 0: all cores (capped at the hardware's)
  /// Refuse a mesh estimated above this many elements (default 200 M).
  std::optional<double> max_elements;
  /// Largest deviation of a meshed volume (area) from the CAD's, as a
  /// fraction (the journal gives percent); default 0.01.
  std::optional<double> volume_tolerance;
  Decompose decompose = Decompose::Auto;
  /// Every volume's element kind, unless its <volume elements> gives
  /// another (`mesh --elements`, <mesh elements>): a kind for all volumes
  /// names no id, so the automatic decomposition's pieces take it too.
  ElementKind elements = ElementKind::Hex;
  /// A volume its scheme accepted and then failed on is meshed again at
  /// half its size, at most this many times (pipeline/finer_retry.h); 0: never.
  int finer_retries = 2;
  static constexpr int kMaxFinerRetries = 4;
  std::vector<CurveSetting> curves;
  std::vector<SurfaceSetting> surfaces;
  std::vector<VolumeSetting> volumes;
  std::vector<VertexTypeSetting> vertex_types;
  SourceLocation where;
};

// ---- quality and export ----------------------------------------------------

/// A threshold on a metric. Elements worse than `limit` are counted; with
/// action Fail the run fails.
struct QualityCheck {
  std::string metric;  ///< "scaled_jacobian", "skew", ...
  std::optional<double> min;
  std::optional<double> max;
  enum class Action { Warn, Fail } action = Action::Warn;
  SourceLocation where;
};

struct ExportSetting {
  std::string file;  ///< the extension decides the format: .exo .msh .vtu .inp
  SourceLocation where;
  bool binary = false;  ///< encoding="binary" (.vtu and .msh only)
};

/// An HTML report of the run (framework/report/html_report.h).
struct ReportSetting {
  std::string file;  ///< .html or .htm
  SourceLocation where;
};

/// A plug-in library of schemes to load before meshing (framework/scheme/plugin.h).
struct PluginSetting {
  std::string file;  ///< as written
  std::string path;  ///< `file` resolved against the journal's directory
  SourceLocation where;
};

// ---- element blocks, side sets and node sets (what solvers see) ----------

/// <block id name volumes|surfaces>: an element block (Exodus), physical
/// group (Gmsh), *ELSET (Abaqus). `volumes` for a volume mesh, `surfaces`
/// for a surface-only mesh (--dim 2); exactly one of them is given.
struct BlockSetting {
  int id = 0;
  std::string name;  ///< "" when not given: written as "block_<id>"
  std::vector<int> volumes;
  std::vector<int> surfaces;
  SourceLocation where;
};

/// <sideset id name surfaces>: the faces of the volume elements on these
/// surfaces (Exodus side set, Gmsh physical surface group, Abaqus *SURFACE).
struct SideSetSetting {
  int id = 0;
  std::string name;  ///< "" when not given: written as "sideset_<id>"
  std::vector<int> surfaces;
  SourceLocation where;
};

/// <nodeset id name surfaces curves vertices>: the nodes on these entities
/// (Exodus node set, Abaqus *NSET); at least one of the three is given.
struct NodeSetSetting {
  int id = 0;
  std::string name;  ///< "" when not given: written as "nodeset_<id>"
  std::vector<int> surfaces;
  std::vector<int> curves;
  std::vector<int> vertices;
  SourceLocation where;
};

/// The groups a journal names. An empty list keeps the default of its kind:
/// a block per volume (per surface in a surface mesh) and element kind, a
/// side set and a node set per meshed surface.
struct GroupSettings {
  std::vector<BlockSetting> blocks;
  std::vector<SideSetSetting> side_sets;
  std::vector<NodeSetSetting> node_sets;
  bool empty() const { return blocks.empty() && side_sets.empty() && node_sets.empty(); }
};

/// A whole journal.
struct Job {
  std::string file;                    ///< the journal path ("" when built in code)
  std::string base_dir;                ///< relative paths inside are resolved against it
  std::vector<PluginSetting> plugins;  ///< loaded after the built-in schemes, in order
  std::vector<GeometryStep> geometry;
  bool imprint_merge = true;  ///< fragment touching solids into a conformal model
  std::optional<MeshSettings> mesh;
  GroupSettings groups;  ///< <block>, <sideset>, <nodeset>
  std::vector<QualityCheck> quality;
  std::vector<ExportSetting> exports;
  std::vector<ReportSetting> reports;
};

}  // namespace cooperage::io
