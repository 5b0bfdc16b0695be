// The pave surface scheme: quality and speed on a fixed set of faces
// (face_models.h), and the 2D core's time against size (linear time).
//
// BM_PaveFace/<k>: the scheme's mesh() on face k (curves meshed before
// timing, interval goals per curve from the face, pave's constraints
// applied); counters: quads, quads_per_s, min_SJ and median_SJ (quad scaled
// Jacobian against the surface normal at the quad's centroid),
// irregular_per_100 (interior nodes whose valence is not 4, per 100 quads),
// peak_MB. With COOPERAGE_FACES_OUT=<dir> set, each face is also written for
// bench/peers/run_faces.py: <name>.brep (the solid), <name>.msh (the face's
// quads, Gmsh 4.1) and <name>.json (the face's curves with their interval
// counts, lengths and centres, and the face's area and centre, so that Gmsh
// can be given the same boundary node counts on the same curves).
//
// BM_Pave2D/<n>: pave_2d alone on the unit square with n (odd) boundary
// segments per side (~n^2 quads); BM_Pave2DHoles/<n>: on a plate with three
// holes, n segments per unit length (~7 n^2 quads); counters also give the CPU milliseconds per
// step (PaveStats: t_boundary, t_cdt, t_recombine, t_split, t_cleanup, t_smooth, t_check) and the
// Laplacian sweeps made.
#include "bench_models.h"
#include "face_models.h"
#include "peak_memory.h"

#include "framework/io/export/write_mesh.h"
#include "framework/pipeline/commit_mesh.h"
#include "framework/quality/quad_metrics.h"
#include "schemes/pave/pave_2d.h"
#include "schemes/pave/quad_quality_2d.h"

#include <Eigen/Geometry>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

using namespace cooperage;

struct QuadStats {
  double min_sj = 0;
  double median_sj = 0;
  double irregular_per_100 = 0;
};

/// Quality of the quads of `surface` in `db` (the surface committed).
QuadStats quad_stats(const geom::Model& model, int surface, const mesh::MeshDB& db) {
  const auto& quads = db.surface(surface).quads;
  const auto& geometry = *model.surface(surface).geometry;
  std::vector<double> sj;
  sj.reserve(quads.size());
  std::map<int, int> valence;  // interior node -> incident quads
  for (const auto& q : quads) {
    quality::QuadNodes p;
    geom::Vec3 centroid = geom::Vec3::Zero();
    for (int k = 0; k < 4; ++k) {
      p[static_cast<size_t>(k)] = db.node(q[static_cast<size_t>(k)]);
      centroid += 0.25 * db.node(q[static_cast<size_t>(k)]);
      const auto& owner = db.owner(q[static_cast<size_t>(k)]);
      if (owner.dim == 2 && owner.id == surface) ++valence[q[static_cast<size_t>(k)]];
    }
    sj.push_back(quality::quad_scaled_jacobian(p, geometry.project(centroid).normal));
  }
  QuadStats s;
  if (sj.empty()) return s;
  const auto mid = sj.begin() + static_cast<std::ptrdiff_t>(sj.size() / 2);
  std::nth_element(sj.begin(), mid, sj.end());
  s.median_sj = *mid;
  s.min_sj = *std::min_element(sj.begin(), sj.end());
  int irregular = 0;
  for (const auto& [node, count] : valence) irregular += count != 4;
  s.irregular_per_100 = 100.0 * irregular / static_cast<double>(quads.size());
  return s;
}

std::string vec_json(const geom::Vec3& v) {
  return "[" + std::to_string(v.x()) + ", " + std::to_string(v.y()) + ", " + std::to_string(v.z()) +
         "]";
}

/// Writes <dir>/<name>.{brep,msh,json} for run_faces.py (see the file comment).
void write_face_files(const std::string& dir, int index, const bench::BenchFace& face,
                      const mesh::MeshDB& committed) {
  const std::string base = dir + "/" + face.name;
  bench::bench_face(index, base + ".brep");  // the solid again (same operations), written as BREP

  // A MeshDB with just the face's quads and their nodes.
  mesh::MeshDB out;
  std::map<int, int> renumber;
  auto& quads = out.mutable_surface(face.surface).quads;
  geom::Vec3 area_centre = geom::Vec3::Zero();
  double area = 0;
  for (const auto& q : committed.surface(face.surface).quads) {
    mesh::Quad r;
    for (size_t k = 0; k < 4; ++k) {
      auto it = renumber.find(q[k]);
      if (it == renumber.end())
        it =
            renumber.emplace(q[k], out.add_node(committed.node(q[k]), committed.owner(q[k]))).first;
      r[k] = it->second;
    }
    quads.push_back(r);
    quality::QuadNodes p;
    for (size_t k = 0; k < 4; ++k) p[k] = committed.node(q[k]);
    const double a = 0.5 * ((p[2] - p[0]).cross(p[3] - p[1])).norm();
    area += a;
    area_centre += a * 0.25 * (p[0] + p[1] + p[2] + p[3]);
  }
  io::write_mesh(base + ".msh", out, face.model);

  std::ofstream json(base + ".json");
  json << "{\"name\": \"" << face.name << "\", \"surface\": " << face.surface
       << ", \"quads\": " << quads.size() << ", \"area\": " << area
       << ", \"centre\": " << vec_json(area_centre / area) << ", \"curves\": [";
  std::set<int> seen;
  bool first = true;
  for (const auto& loop : face.model.surface(face.surface).loops)
    for (const auto& use : loop.uses) {
      if (!seen.insert(use.curve).second) continue;
      const auto& chain = committed.curve_nodes(use.curve);
      geom::Vec3 centre = geom::Vec3::Zero();
      double length = 0;
      for (size_t i = 0; i + 1 < chain.size(); ++i) {
        const geom::Vec3 a = committed.node(chain[i]), b = committed.node(chain[i + 1]);
        length += (b - a).norm();
        centre += (b - a).norm() * 0.5 * (a + b);
      }
      json << (first ? "" : ", ") << "{\"id\": " << use.curve
           << ", \"intervals\": " << chain.size() - 1
           << ", \"length\": " << face.model.curve(use.curve).length
           << ", \"centre\": " << vec_json(centre / length) << "}";
      first = false;
    }
  json << "]}\n";
}

void BM_PaveFace(benchmark::State& state) {
  static std::map<int, bench::BenchFace> faces;  // built once per process
  const int k = static_cast<int>(state.range(0));
  if (!faces.count(k)) faces.emplace(k, bench::bench_face(k));
  const bench::BenchFace& face = faces.at(k);
  const scheme::SurfaceScheme* pave = bench::builtin_registry().surface_scheme("pave");
  const mesh::MeshDB db = bench::curves_for_surface(face.model, *pave, face.surface, face.size);
  const scheme::SurfaceView view{face.model, face.surface, &db};
  scheme::EntityMesh m;
  for (auto _ : state) {
    m = pave->mesh(view, {1.0});
    benchmark::DoNotOptimize(m.coords.data());
  }
  mesh::MeshDB committed = db;
  const size_t quads = m.quads.size();
  pipeline::commit_surface(m, face.surface, committed);
  const QuadStats s = quad_stats(face.model, face.surface, committed);
  state.SetLabel(face.name);
  state.counters["quads"] = static_cast<double>(quads);
  state.counters["quads_per_s"] =
      benchmark::Counter(static_cast<double>(quads), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["min_SJ"] = s.min_sj;
  state.counters["median_SJ"] = s.median_sj;
  state.counters["irregular_per_100"] = s.irregular_per_100;
  state.counters["peak_MB"] = static_cast<double>(bench::peak_memory_bytes()) / 1e6;

  static std::set<int> written;
  if (const char* dir = std::getenv("COOPERAGE_FACES_OUT"); dir && written.insert(k).second)
    write_face_files(dir, k, face, committed);
}
BENCHMARK(BM_PaveFace)->DenseRange(0, 7)->Unit(benchmark::kMillisecond);

/// pave_2d on `loops`, repeated, with its per-step times as counters.
void run_pave_2d(benchmark::State& state, const std::vector<std::vector<Eigen::Vector2d>>& loops) {
  size_t quads = 0;
  pave::PaveStats stats, sum;
  pave::PaveOptions options;
  options.stats = &stats;
  pave::QuadMesh2D last;
  for (auto _ : state) {
    pave::QuadMesh2D m = pave::pave_2d(loops, options);
    quads = m.quads.size();
    benchmark::DoNotOptimize(m.points.data());
    last = std::move(m);
    sum.boundary += stats.boundary;
    sum.triangulate += stats.triangulate;
    sum.recombine += stats.recombine;
    sum.split += stats.split;
    sum.cleanup += stats.cleanup;
    sum.smooth += stats.smooth;
    sum.check += stats.check;
  }
  const auto ms = [&](double seconds) {
    return benchmark::Counter(1e3 * seconds, benchmark::Counter::kAvgIterations);
  };
  state.counters["t_boundary"] = ms(sum.boundary);
  state.counters["t_cdt"] = ms(sum.triangulate);
  state.counters["t_recombine"] = ms(sum.recombine);
  state.counters["t_split"] = ms(sum.split);
  state.counters["t_cleanup"] = ms(sum.cleanup);
  state.counters["t_smooth"] = ms(sum.smooth);
  state.counters["t_check"] = ms(sum.check);
  state.counters["sweeps"] = stats.sweeps;
  state.counters["attempts"] = stats.attempts;
  state.counters["kept"] = stats.kept;
  std::vector<double> sj(last.quads.size());
  for (size_t k = 0; k < sj.size(); ++k)
    sj[k] = pave::detail::scaled_jacobian_2d(last.points, last.quads[k]);
  if (!sj.empty()) {
    std::sort(sj.begin(), sj.end());
    state.counters["min_SJ"] = sj.front();
    state.counters["median_SJ"] = sj[sj.size() / 2];
  }
  state.counters["quads"] = static_cast<double>(quads);
  state.counters["quads_per_s"] =
      benchmark::Counter(static_cast<double>(quads), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_MB"] = static_cast<double>(bench::peak_memory_bytes()) / 1e6;
}

// Unit square, n boundary segments per side, counter-clockwise, ~n^2 quads.
// n is odd: every side has an odd edge, the rows from opposite sides are
// half a spacing apart and meet at seams (with n even the frontal mesh is
// the structured grid, ~1.8 M quads/s: no test of the general path).
void BM_Pave2D(benchmark::State& state) {
  run_pave_2d(state, bench::unit_square_2d(static_cast<int>(state.range(0))));
}
// ~5.6k, ~55k, ~555k quads.
BENCHMARK(BM_Pave2D)->Arg(75)->Arg(235)->Arg(745)->Unit(benchmark::kMillisecond);

// The 4 x 2 plate with three round holes of the pave tests, n boundary
// segments per unit length (~7 n^2 quads): unstructured, fronts collide
// around and between the holes, so both coarse triangulations run.
void BM_Pave2DHoles(benchmark::State& state) {
  run_pave_2d(state, bench::plate_with_holes_2d(static_cast<int>(state.range(0))));
}
// ~5k, ~50k, ~500k quads.
BENCHMARK(BM_Pave2DHoles)->Arg(27)->Arg(85)->Arg(267)->Unit(benchmark::kMillisecond);

}  // namespace
