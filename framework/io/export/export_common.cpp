#include "framework/io/export/export_common.h"

#include "framework/quality/hex_metrics.h"
#include "framework/quality/quad_metrics.h"
#include "framework/quality/tri_metrics.h"
#include "framework/quality/wedge_metrics.h"

#include "framework/core/error.h"
#include "framework/core/text.h"

#include <Eigen/Geometry>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <streambuf>
#include <utility>

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

namespace cooperage::io::detail {
namespace {

using geom::Vec3;

template <size_t N>
void check_nodes(const std::array<int, N>& e, int n_nodes, EntityRef where, const char* kind,
                 size_t index) {
  for (int v : e) {
    if (v < 0 || v >= n_nodes) {
      throw MeshingError(ErrorCode::InvalidInput, where,
                         std::string(kind) + " " + std::to_string(index) + " references node " +
                             std::to_string(v) + " (the mesh has " + std::to_string(n_nodes) +
                             " nodes)");
    }
  }
}

template <class T>
void check_all(const std::vector<T>& elems, int n_nodes, EntityRef where, const char* kind) {
  for (size_t i = 0; i < elems.size(); ++i) check_nodes(elems[i], n_nodes, where, kind, i);
}

}  // namespace

void validate_mesh(const mesh::MeshDB& db, const geom::Model& model) {
  const int n = static_cast<int>(db.node_count());
  const int n_surfaces = static_cast<int>(model.surfaces().size());
  const int n_volumes = static_cast<int>(model.volumes().size());
  for (const auto& [id, s] : db.surfaces()) {
    if (id < 1 || id > n_surfaces) {
      throw MeshingError(
          ErrorCode::InvalidInput, EntityRef::surface(id),
          "is meshed but not in the model (" + std::to_string(n_surfaces) + " surfaces)");
    }
    check_all(s.quads, n, EntityRef::surface(id), "quad");
    check_all(s.tris, n, EntityRef::surface(id), "triangle");
  }
  for (const auto& [id, v] : db.volumes()) {
    if (id < 1 || id > n_volumes) {
      throw MeshingError(
          ErrorCode::InvalidInput, EntityRef::volume(id),
          "is meshed but not in the model (" + std::to_string(n_volumes) + " volumes)");
    }
    check_all(v.hexes, n, EntityRef::volume(id), "hex");
    check_all(v.wedges, n, EntityRef::volume(id), "wedge");
  }
  bool any = false;
  for (const auto& [id, s] : db.surfaces()) any = any || s.size() > 0;
  for (const auto& [id, v] : db.volumes()) any = any || v.size() > 0;
  if (!any) throw MeshingError(ErrorCode::InvalidInput, "the mesh has no elements to export");
  for (int i = 0; i < n; ++i) {
    if (!db.node(i).allFinite()) {
      throw MeshingError(ErrorCode::InvalidInput,
                         "node " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
}

bool has_volume_elements(const mesh::MeshDB& db) {
  for (const auto& [id, v] : db.volumes()) {
    if (v.size() > 0) return true;
  }
  return false;
}

namespace {

/// 64 unpredictable bits (getrandom; the clock and a counter if it fails).
std::uint64_t random_bits() {
  std::uint64_t v = 0;
  if (::getrandom(&v, sizeof v, GRND_NONBLOCK) == static_cast<ssize_t>(sizeof v)) return v;
  static std::atomic<std::uint64_t> counter{0};
  const auto t = static_cast<std::uint64_t>(
      std::chrono::high_resolution_clock::now().time_since_epoch().count());
  return t * 0x9E3779B97F4A7C15ull ^ (counter++ << 32) ^ static_cast<std::uint64_t>(::getpid());
}

/// An ostream over a file descriptor it owns; every write is checked.
class FdBuffer : public std::streambuf {
 public:
  explicit FdBuffer(int fd) : fd_(fd) { setp(buf_, buf_ + sizeof buf_); }
  ~FdBuffer() override { close(); }
  /// Flushes and closes; false when any write or the close failed.
  bool close() {
    if (fd_ < 0) return ok_;
    ok_ = flush_buffer() && ok_;
    ok_ = ::close(fd_) == 0 && ok_;
    fd_ = -1;
    return ok_;
  }

 protected:
  int_type overflow(int_type c) override {
    if (!flush_buffer()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return flush_buffer() ? 0 : -1; }

 private:
  bool flush_buffer() {
    const char* p = pbase();
    std::size_t left = static_cast<std::size_t>(pptr() - pbase());
    while (left > 0 && ok_) {
      const ssize_t n = ::write(fd_, p, left);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0)
        ok_ = false;
      else {
        p += n;
        left -= static_cast<std::size_t>(n);
      }
    }
    setp(buf_, buf_ + sizeof buf_);
    return ok_;
  }

  int fd_;
  bool ok_ = true;
  char buf_[1 << 16];
};

}  // namespace

std::string temp_path_for(const std::string& path) {
  const std::filesystem::path p(path);
  std::string name = p.filename().string().substr(0, 32);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(random_bits()));
  return (p.parent_path() / ("." + name + "." + hex + ".tmp")).string();
}

void remove_temp_file(const std::string& tmp) noexcept { ::unlink(tmp.c_str()); }

int replace_file(const std::string& from, const std::string& to) noexcept {
  struct stat st {};
  if (::lstat(to.c_str(), &st) == 0 && S_ISREG(st.st_mode)) ::unlink(to.c_str());
  return std::rename(from.c_str(), to.c_str()) == 0 ? 0 : errno;
}

void commit_temp_file(const std::string& tmp, const std::string& path) {
  if (const int err = replace_file(tmp, path); err != 0) {
    remove_temp_file(tmp);
    throw MeshingError(ErrorCode::FileNotFound,
                       "cannot write '" + clip_path(path) + "' (" + std::strerror(err) + ")");
  }
}

void write_text_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
  std::string tmp;
  int fd = -1;
  for (int attempt = 0; attempt < 8 && fd < 0; ++attempt) {
    tmp = temp_path_for(path);
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0) {
    const int err = errno;
    throw MeshingError(ErrorCode::FileNotFound,
                       "cannot write '" + clip_path(path) + "' (" + std::strerror(err) + ")");
  }
  try {
    FdBuffer buffer(fd);
    std::ostream out(&buffer);
    write(out);
    out.flush();
    if (!out || !buffer.close())
      throw MeshingError(ErrorCode::FileNotFound,
                         "cannot write '" + clip_path(path) + "' (the disk may be full)");
  } catch (...) {
    remove_temp_file(tmp);
    throw;
  }
  commit_temp_file(tmp, path);
}

// ---- faces -------------------------------------------------------------------

FaceFinder::Key FaceFinder::key_of(const int* nodes, int n) {
  Key k{-1, -1, -1, -1};
  // Insertion sort of at most 4 values (std::sort trips -Warray-bounds here).
  for (int i = 0; i < n; ++i) {
    int j = i;
    for (; j > 0 && k[static_cast<size_t>(j - 1)] > nodes[i]; --j) {
      k[static_cast<size_t>(j)] = k[static_cast<size_t>(j - 1)];
    }
    k[static_cast<size_t>(j)] = nodes[i];
  }
  return k;
}

FaceFinder::FaceFinder(const mesh::VolumeMeshData& vol, const FaceTable& hex_faces,
                       const FaceTable& wedge_faces, const std::vector<bool>& wanted) {
  // The scan of every element's sides runs in parallel over fixed chunks,
  // each collecting its candidate sides in element order; they are indexed
  // chunk after chunk, so the first element with a face wins exactly as in
  // one sequential pass (an interior face is shared by two elements of the
  // volume; boundary faces are unique).
  using Candidate = std::pair<Key, FaceHit>;
  auto scan = [&wanted](const int* elem, const FaceTable& table, bool wedge, int index,
                        std::vector<Candidate>& out) {
    for (size_t s = 0; s < table.size(); ++s) {
      int nodes[4];
      const int n = static_cast<int>(table[s].size());
      bool all_wanted = true;
      for (int i = 0; i < n && all_wanted; ++i) {
        nodes[i] = elem[table[s][static_cast<size_t>(i)]];
        all_wanted = wanted[static_cast<size_t>(nodes[i])];
      }
      if (all_wanted)
        out.emplace_back(key_of(nodes, n), FaceHit{wedge, index, static_cast<int>(s)});
    }
  };
  constexpr size_t kChunk = 16384;
  const size_t nh = vol.hexes.size(), total = nh + vol.wedges.size();
  std::vector<std::vector<Candidate>> found((total + kChunk - 1) / kChunk);
  tbb::parallel_for(size_t{0}, found.size(), [&](size_t c) {
    for (size_t e = c * kChunk; e < std::min(total, (c + 1) * kChunk); ++e) {
      if (e < nh) {
        scan(vol.hexes[e].data(), hex_faces, false, static_cast<int>(e), found[c]);
      } else {
        scan(vol.wedges[e - nh].data(), wedge_faces, true, static_cast<int>(e - nh), found[c]);
      }
    }
  });
  // One sorted array instead of a tree: a stable sort keeps the chunks'
  // order among equal keys, and the first of each run is the one kept.
  size_t count = 0;
  for (const auto& chunk : found) count += chunk.size();
  faces_.reserve(count);
  for (const auto& chunk : found) faces_.insert(faces_.end(), chunk.begin(), chunk.end());
  auto by_key = [](const Candidate& a, const Candidate& b) { return a.first < b.first; };
  std::stable_sort(faces_.begin(), faces_.end(), by_key);
  faces_.erase(
      std::unique(faces_.begin(), faces_.end(),
                  [](const Candidate& a, const Candidate& b) { return a.first == b.first; }),
      faces_.end());
}

FaceHit FaceFinder::find(const int* nodes, int n) const {
  const Key key = key_of(nodes, n);
  auto it =
      std::lower_bound(faces_.begin(), faces_.end(), key,
                       [](const std::pair<Key, FaceHit>& a, const Key& k) { return a.first < k; });
  return it == faces_.end() || it->first != key ? FaceHit{} : it->second;
}

const FaceTable& exodus_hex_sides() {
  static const FaceTable t{{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                           {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  return t;
}
const FaceTable& exodus_wedge_sides() {
  static const FaceTable t{{0, 1, 4, 3}, {1, 2, 5, 4}, {0, 3, 5, 2}, {0, 2, 1}, {3, 4, 5}};
  return t;
}
const FaceTable& abaqus_hex_faces() {
  static const FaceTable t{{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1},
                           {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
  return t;
}
const FaceTable& abaqus_wedge_faces() {
  static const FaceTable t{{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
  return t;
}

std::map<int, std::vector<FaceHit>> surface_faces(const mesh::MeshDB& db, const geom::Model& model,
                                                  const FaceTable& hex_faces,
                                                  const FaceTable& wedge_faces) {
  std::map<int, FaceFinder> finders;
  std::map<int, std::vector<FaceHit>> result;
  for (const auto& [sid, s] : db.surfaces()) {
    const auto& vols = model.surface(sid).volumes;
    if (vols.empty() || s.size() == 0) continue;
    const int vid = vols.front();
    if (!db.volume_meshed(vid) || db.volume(vid).size() == 0) continue;
    auto it = finders.find(vid);
    if (it == finders.end()) {
      // Nodes of every surface element this volume's sides must carry.
      std::vector<bool> wanted(db.node_count(), false);
      for (const auto& [other, mesh] : db.surfaces()) {
        const auto& owners = model.surface(other).volumes;
        if (owners.empty() || owners.front() != vid) continue;
        for (const auto& q : mesh.quads) {
          for (int n : q) wanted[static_cast<size_t>(n)] = true;
        }
        for (const auto& t : mesh.tris) {
          for (int n : t) wanted[static_cast<size_t>(n)] = true;
        }
      }
      it = finders.emplace(vid, FaceFinder(db.volume(vid), hex_faces, wedge_faces, wanted)).first;
    }
    std::vector<FaceHit>& hits = result[sid];
    hits.reserve(s.size());
    const int surface_id = sid;  // C++17 lambdas cannot capture a structured binding (clang)
    auto look = [&](const int* nodes, int n, const char* kind, size_t i) {
      FaceHit h = it->second.find(nodes, n);
      if (h.element < 0) {
        throw MeshingError(ErrorCode::InvalidInput, EntityRef::surface(surface_id),
                           std::string(kind) + " " + std::to_string(i) +
                               " is not a face of any element of volume " + std::to_string(vid) +
                               " (non-conformal mesh)");
      }
      hits.push_back(h);
    };
    for (size_t i = 0; i < s.quads.size(); ++i) look(s.quads[i].data(), 4, "quad", i);
    for (size_t i = 0; i < s.tris.size(); ++i) look(s.tris[i].data(), 3, "triangle", i);
  }
  return result;
}

std::vector<int> surface_node_set(const mesh::SurfaceMeshData& s) {
  // A bit per node between the smallest and largest, read out in order: a
  // surface's nodes are a fraction of a big mesh's, and sorting every
  // element corner (four per quad) cost more than the scan of the bits.
  int lo = std::numeric_limits<int>::max(), hi = -1;
  auto bounds = [&](const auto& elems) {
    for (const auto& e : elems)
      for (int n : e) lo = std::min(lo, n), hi = std::max(hi, n);
  };
  bounds(s.quads);
  bounds(s.tris);
  std::vector<int> nodes;
  if (hi < lo) return nodes;
  std::vector<std::uint64_t> bits(static_cast<size_t>(hi - lo) / 64 + 1, 0);
  size_t count = 0;
  auto mark = [&](const auto& elems) {
    for (const auto& e : elems)
      for (int n : e) {
        const auto i = static_cast<size_t>(n - lo);
        const std::uint64_t bit = std::uint64_t{1} << (i % 64);
        count += (bits[i / 64] & bit) == 0;
        bits[i / 64] |= bit;
      }
  };
  mark(s.quads);
  mark(s.tris);
  nodes.reserve(count);
  for (size_t w = 0; w < bits.size(); ++w)
    for (std::uint64_t b = bits[w]; b != 0; b &= b - 1)
      nodes.push_back(lo + static_cast<int>(w * 64 + static_cast<size_t>(__builtin_ctzll(b))));
  return nodes;
}

// ---- scaled Jacobian (framework/quality, Verdict definitions) --------------

namespace {
template <size_t N>
std::array<Vec3, N> gather(const std::array<int, N>& e, const std::vector<Vec3>& x) {
  std::array<Vec3, N> p;
  for (size_t i = 0; i < N; ++i) p[i] = x[static_cast<size_t>(e[i])];
  return p;
}
}  // namespace

double scaled_jacobian(const mesh::Hex& h, const std::vector<Vec3>& x) {
  return quality::hex_scaled_jacobian(gather(h, x));
}
double scaled_jacobian(const mesh::Wedge& w, const std::vector<Vec3>& x) {
  return quality::wedge_scaled_jacobian(gather(w, x));
}
double scaled_jacobian(const mesh::Quad& q, const std::vector<Vec3>& x) {
  return quality::quad_scaled_jacobian(gather(q, x));
}
double scaled_jacobian(const mesh::Tri& t, const std::vector<Vec3>& x) {
  return quality::tri_scaled_jacobian(gather(t, x));
}

std::string volume_label(const geom::Model& model, int volume_id) {
  auto clean = [](const std::string& name) {
    std::string s = name;
    for (char& c : s) {
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) c = '_';
    }
    return s;
  };
  const std::string own = clean(model.volume(volume_id).name.substr(0, kMaxLabelLength));
  const std::string fallback = "V" + std::to_string(volume_id);
  if (own.empty() || !std::isalpha(static_cast<unsigned char>(own[0]))) return fallback;
  for (const auto& v : model.volumes()) {
    if (v.id != volume_id && clean(v.name.substr(0, kMaxLabelLength)) == own) return fallback;
  }
  return own;
}

}  // namespace cooperage::io::detail
