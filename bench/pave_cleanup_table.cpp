// pave's clean-up on arrays (cleanup_2d.h) against the half-edge clean-up
// with edge rotation (halfedge_cleanup.h), and the half-edge one without
// rotation, over a fixed corpus (issue 19 item 5; bench/RESULTS.md,
// "2026-12-02 (session 4)"):
//  * pave's named 2D test faces and the random test faces 1000-1239
//    (tests/schemes/pave/pave_test_util.h);
//  * the BM_Pave2D / BM_Pave2DHoles faces (pave_bench.cpp), also for speed;
//  * the BM_PaveFace CAD faces (face_models.h), through the scheme;
//  * with FILE arguments: every face the selector gives to pave when FILE
//    is meshed as `cooperage mesh FILE --dim 2 --size D/40` (D: diagonal of
//    the model's bounding box), re-meshed on the run's curve meshes.
// Per face: quads, irregular interior nodes per 100 quads, minimum and
// median scaled Jacobian (2D faces in the plane; CAD faces on the surface,
// against its normal at the quad's centroid, as pave_bench reports), and the
// clean-up's CPU time. Prints Markdown tables.
//
// usage: pave_cleanup_table [--div N] [--min-quality Q] [--fixed-boundary-counts] [FILE ...]
// (the last two: HalfEdgeCleanupOptions of the half-edge columns)
#include "bench_models.h"
#include "face_models.h"
#include "pave_test_util.h"

#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/mesher.h"
#include "framework/quality/quad_metrics.h"
#include "schemes/pave/pave_scheme.h"
#include "selector/select_schemes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace cooperage;
using pave::testing::Loops;

/// The clean-ups compared, in column order.
struct Variant {
  const char* name;
  pave::PaveOptions options;
};

/// The half-edge settings of the command line (--min-quality,
/// --fixed-boundary-counts) for the half-edge columns.
pave::detail::HalfEdgeCleanupOptions g_halfedge;

std::vector<Variant> variants() {
  pave::PaveOptions arrays, halfedge, no_rotation, convert;
  halfedge.halfedge_cleanup = no_rotation.halfedge_cleanup = convert.halfedge_cleanup = true;
  halfedge.halfedge = no_rotation.halfedge = g_halfedge;
  no_rotation.halfedge.rotate = false;
  convert.halfedge.max_passes = 0;  // the conversions alone: what the half-edge mesh costs
  return {{"arrays", arrays},
          {"half-edge", halfedge},
          {"half-edge, no rotation", no_rotation},
          {"half-edge, conversions only (no clean-up)", convert}};
}

struct Result {
  bool ok = false;
  int quads = 0, irregular = 0;
  double min_sj = 0, median_sj = 0, cleanup_ms = 0;
};

void finish(Result& r, std::vector<double> sj) {
  r.ok = !sj.empty();
  r.quads = static_cast<int>(sj.size());
  if (sj.empty()) return;
  std::sort(sj.begin(), sj.end());
  r.min_sj = sj.front();
  r.median_sj = sj[sj.size() / 2];
}

Result run_2d(const Loops& loops, pave::PaveOptions options) {
  pave::PaveStats stats;
  options.stats = &stats;
  Result r;
  pave::QuadMesh2D m;
  try {
    m = pave::pave_2d(loops, options);
  } catch (const MeshingError&) {
    return r;
  }
  std::vector<double> sj;
  std::vector<int> count(m.points.size(), 0);
  for (const auto& q : m.quads) {
    sj.push_back(pave::detail::scaled_jacobian_2d(m.points, q));
    for (int v : q) ++count[static_cast<size_t>(v)];
  }
  for (size_t i = static_cast<size_t>(m.boundary_count); i < count.size(); ++i)
    r.irregular += count[i] != 4;
  r.cleanup_ms = 1e3 * stats.cleanup;
  finish(r, sj);
  return r;
}

/// The scheme on surface `sid` whose curves are meshed in db.
Result run_scheme(const geom::Model& model, int sid, const mesh::MeshDB& db,
                  pave::PaveOptions options) {
  pave::PaveStats stats;
  options.stats = &stats;
  const pave::PaveScheme scheme(options);
  Result r;
  scheme::EntityMesh m;
  try {
    m = scheme.mesh(scheme::SurfaceView{model, sid, &db}, scheme::Settings{});
  } catch (const MeshingError&) {
    return r;
  }
  const auto& geometry = *model.surface(sid).geometry;
  std::vector<double> sj;
  std::vector<int> count(m.coords.size(), 0);
  for (const auto& q : m.quads) {
    quality::QuadNodes p;
    geom::Vec3 centroid = geom::Vec3::Zero();
    for (size_t k = 0; k < 4; ++k) {
      p[k] = m.coords[static_cast<size_t>(q[k])];
      centroid += 0.25 * p[k];
      ++count[static_cast<size_t>(q[k])];
    }
    sj.push_back(quality::quad_scaled_jacobian(p, geometry.project(centroid).normal));
  }
  for (size_t i = 0; i < count.size(); ++i) r.irregular += m.global[i] < 0 && count[i] != 4;
  r.cleanup_ms = 1e3 * stats.cleanup;
  finish(r, sj);
  return r;
}

std::string cell(const Result& r) {
  if (!r.ok) return "failed | | | |";
  char s[160];
  std::snprintf(s, sizeof s, "%d | %.1f | %.3f | %.3f | %.2f", r.quads,
                100.0 * r.irregular / std::max(r.quads, 1), r.min_sj, r.median_sj, r.cleanup_ms);
  return s;
}

void header(const char* first) {
  std::printf("\n| %s |", first);
  for (const auto& v : variants())
    std::printf(" %s: quads | irr/100 | min SJ | median SJ | clean-up ms |", v.name);
  std::printf("\n|---|");
  for (size_t k = 0; k < variants().size(); ++k) std::printf("---|---|---|---|---|");
  std::printf("\n");
}

void row(const std::string& name, const std::vector<Result>& rs) {
  std::printf("| %s |", name.c_str());
  for (const auto& r : rs) std::printf(" %s |", cell(r).c_str());
  std::printf("\n");
}

/// Sums over a set of faces, per variant, against the first variant.
struct Totals {
  int faces = 0, failed = 0, quads = 0, irregular = 0, lower_min = 0, higher_min = 0;
  double worst = 2, min_sum = 0, median_sum = 0, worst_drop = 0, ms = 0;
  void add(const Result& r, const Result& base) {
    ++faces;
    if (!r.ok) {
      ++failed;
      return;
    }
    quads += r.quads;
    irregular += r.irregular;
    worst = std::min(worst, r.min_sj);
    min_sum += r.min_sj;
    median_sum += r.median_sj;
    ms += r.cleanup_ms;
    if (!base.ok) return;
    const double d = r.min_sj - base.min_sj;
    lower_min += d < -0.01;
    higher_min += d > 0.01;
    worst_drop = std::min(worst_drop, d);
  }
};

void print_totals(const char* what, const std::vector<Totals>& t) {
  std::printf(
      "\n%s\n\n| clean-up | faces | failed | quads | irr/100 | worst min SJ | mean min SJ "
      "| mean median SJ | faces min SJ < arrays - 0.01 | > arrays + 0.01 | largest min "
      "SJ drop | clean-up ms |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
      what);
  const auto vs = variants();
  for (size_t k = 0; k < t.size(); ++k) {
    const Totals& x = t[k];
    const int ok = std::max(x.faces - x.failed, 1);
    std::printf("| %s | %d | %d | %d | %.2f | %.3f | %.4f | %.4f | %d | %d | %.3f | %.1f |\n",
                vs[k].name, x.faces, x.failed, x.quads, 100.0 * x.irregular / std::max(x.quads, 1),
                x.worst, x.min_sum / ok, x.median_sum / ok, x.lower_min, x.higher_min, x.worst_drop,
                x.ms);
  }
}

std::vector<Result> all_2d(const Loops& loops) {
  std::vector<Result> rs;
  for (const auto& v : variants()) rs.push_back(run_2d(loops, v.options));
  return rs;
}

void add_totals(std::vector<Totals>& t, const std::vector<Result>& rs) {
  t.resize(rs.size());
  for (size_t k = 0; k < rs.size(); ++k) t[k].add(rs[k], rs[0]);
}

/// Every pave face of FILE meshed with --dim 2 --size D/div.
void real_cad(const std::string& file, double div, std::vector<Totals>& all) {
  const std::string name = file.substr(file.find_last_of('/') + 1);
  geom::Model model;
  pipeline::MeshResult run;
  try {
    model = pipeline::load_any(file);
    const geom::BoundingBox box = model.box();
    io::MeshSettings settings;
    settings.size = (box.max - box.min).norm() / div;
    pipeline::MeshOptions options = selector::mesh_options(2, 1);
    options.allow_partial = true;
    run = pipeline::mesh_model(model, settings, bench::builtin_registry(), options);
  } catch (const std::exception& e) {
    std::printf("| %s | not meshed: %s |\n", name.c_str(), e.what());
    return;
  }
  std::vector<Totals> t;
  for (const auto& [sid, entry] : run.plan.surfaces) {
    if (entry.scheme != "pave") continue;
    std::vector<Result> rs;
    for (const auto& v : variants()) rs.push_back(run_scheme(model, sid, run.mesh, v.options));
    add_totals(t, rs);
    add_totals(all, rs);
  }
  std::printf("| %s |", name.c_str());
  for (const Totals& x : t) {
    std::printf(" %d / %d | %.2f | %.3f | %d |", x.faces, x.failed,
                100.0 * x.irregular / std::max(x.quads, 1), x.worst, x.lower_min);
  }
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  double div = 40;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--div" && i + 1 < argc) {
      div = std::atof(argv[++i]);
    } else if (a == "--min-quality" && i + 1 < argc) {
      g_halfedge.min_quality = std::atof(argv[++i]);
    } else if (a == "--fixed-boundary-counts") {
      g_halfedge.boundary_counts = false;
    } else {
      files.push_back(a);
    }
  }

  std::vector<Totals> named, random, bench2d, cad, real;
  header("pave test face (2D)");
  for (const auto& f : pave::testing::benchmark_faces()) {
    const auto rs = all_2d(f.loops);
    row(f.name, rs);
    add_totals(named, rs);
  }
  for (unsigned seed = 1000; seed < 1240; ++seed)
    add_totals(random, all_2d(pave::testing::random_face(seed)));

  header("BM_Pave2D faces (2D)");
  for (int n : {75, 235, 745}) {
    const auto rs = all_2d(bench::unit_square_2d(n));
    row("square n=" + std::to_string(n), rs);
    add_totals(bench2d, rs);
  }
  for (int n : {27, 85, 267}) {
    const auto rs = all_2d(bench::plate_with_holes_2d(n));
    row("holes n=" + std::to_string(n), rs);
    add_totals(bench2d, rs);
  }

  header("BM_PaveFace (on the surface)");
  const scheme::SurfaceScheme& pave_scheme = *bench::builtin_registry().surface_scheme("pave");
  for (int k = 0; k < bench::face_count(); ++k) {
    const bench::BenchFace face = bench::bench_face(k);
    const mesh::MeshDB db =
        bench::curves_for_surface(face.model, pave_scheme, face.surface, face.size);
    std::vector<Result> rs;
    for (const auto& v : variants())
      rs.push_back(run_scheme(face.model, face.surface, db, v.options));
    row(face.name, rs);
    add_totals(cad, rs);
  }

  if (!files.empty()) {
    std::printf(
        "\nReal CAD, pave faces of `cooperage mesh FILE --dim 2 --size D/%g` "
        "(per clean-up: faces / failed | irr/100 | worst min SJ | faces min SJ < arrays - "
        "0.01)\n\n| file |",
        div);
    for (const auto& v : variants())
      std::printf(" %s: faces / failed | irr/100 | worst min SJ | min SJ lower |", v.name);
    std::printf("\n|---|");
    for (size_t k = 0; k < variants().size(); ++k) std::printf("---|---|---|---|");
    std::printf("\n");
    for (const auto& f : files) real_cad(f, div, real);
  }

  print_totals("pave test faces (2D)", named);
  print_totals("random test faces 1000-1239 (2D)", random);
  print_totals("BM_Pave2D / BM_Pave2DHoles faces (2D)", bench2d);
  print_totals("BM_PaveFace CAD faces (on the surface)", cad);
  if (!real.empty()) print_totals("real-CAD pave faces (on the surface)", real);
  return 0;
}
