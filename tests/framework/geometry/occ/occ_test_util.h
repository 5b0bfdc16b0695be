// Helpers for the OpenCASCADE backend tests: a scratch directory, loop
// sampling and small model queries. Uses the Workbench / Model API only.
#pragma once

#include "framework/core/error.h"
#include "framework/geometry/model.h"
#include "framework/geometry/occ/workbench.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace cooperage::occ::test {

using geom::Model;
using geom::Vec2;

/// A fresh directory removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("cooperage-occ-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

/// Points along a loop, in loop order (n samples per curve, end excluded).
inline std::vector<Vec3> sample_loop(const Model& m, const geom::Loop& loop, int n = 16) {
  std::vector<Vec3> pts;
  for (const auto& use : loop.uses) {
    const auto& g = *m.curve(use.curve).geometry;
    const auto r = g.range();
    for (int i = 0; i < n; ++i) {
      const double s = static_cast<double>(i) / n;
      const double t = use.sense == geom::Sense::Forward ? r.first + s * (r.second - r.first)
                                                         : r.second - s * (r.second - r.first);
      pts.push_back(g.point(t));
    }
  }
  return pts;
}

/// Vector area of a closed polygon: normal * enclosed area (right-hand rule).
inline Vec3 area_vector(const std::vector<Vec3>& pts) {
  Vec3 a = Vec3::Zero();
  for (size_t i = 0; i < pts.size(); ++i) a += pts[i].cross(pts[(i + 1) % pts.size()]);
  return 0.5 * a;
}

inline Vec2 uv_centre(const geom::Surface& s) {
  const auto b = s.geometry->uv_bounds();
  return Vec2(0.5 * (b.first.x() + b.first.y()), 0.5 * (b.second.x() + b.second.y()));
}

inline int count_shared_surfaces(const Model& m) {
  int n = 0;
  for (const auto& s : m.surfaces()) n += s.volumes.size() == 2 ? 1 : 0;
  return n;
}

inline double total_volume(const Model& m) {
  double v = 0;
  for (const auto& vol : m.volumes()) v += vol.volume;
  return v;
}

/// Expects fn to throw MeshingError with the code; returns its message.
inline std::string expect_error(ErrorCode code, const std::function<void()>& fn) {
  try {
    fn();
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "unexpected exception: " << e.what();
    return {};
  }
  ADD_FAILURE() << "no exception thrown";
  return {};
}

/// The whole file at `path`, bytes as they are.
inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline bool near_rel(double a, double b, double rel, double abs_tol = 1e-12) {
  return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b)) + abs_tol;
}

}  // namespace cooperage::occ::test
