#include "framework/mesh/tfi.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cooperage::mesh {

std::vector<double> arc_fractions(const std::vector<Vec3>& points) {
  const size_t n = points.size();
  std::vector<double> f(n, 0.0);
  if (n < 2) return f;
  for (size_t i = 1; i < n; ++i) f[i] = f[i - 1] + (points[i] - points[i - 1]).norm();
  const double total = f.back();
  for (size_t i = 0; i < n; ++i) {
    f[i] = total > 0 ? f[i] / total : static_cast<double>(i) / static_cast<double>(n - 1);
  }
  f.back() = 1.0;
  return f;
}

Grid2 tfi_2d(const std::vector<Vec3>& bottom, const std::vector<Vec3>& top,
             const std::vector<Vec3>& left, const std::vector<Vec3>& right) {
  Grid2 g;
  g.n = static_cast<int>(bottom.size()) - 1;
  g.m = static_cast<int>(left.size()) - 1;
  g.at.assign((static_cast<size_t>(g.n) + 1) * (static_cast<size_t>(g.m) + 1), Vec3::Zero());
  const std::vector<double> fb = arc_fractions(bottom), ft = arc_fractions(top);
  const std::vector<double> fl = arc_fractions(left), fr = arc_fractions(right);
  const Vec3& p00 = bottom.front();
  const Vec3& p10 = bottom.back();
  const Vec3& p01 = top.front();
  const Vec3& p11 = top.back();
  for (int i = 0; i <= g.n; ++i) {
    const size_t ui = static_cast<size_t>(i);
    for (int j = 0; j <= g.m; ++j) {
      const size_t uj = static_cast<size_t>(j);
      if (j == 0) {
        g(i, j) = bottom[ui];
        continue;
      }
      if (j == g.m) {
        g(i, j) = top[ui];
        continue;
      }
      if (i == 0) {
        g(i, j) = left[uj];
        continue;
      }
      if (i == g.n) {
        g(i, j) = right[uj];
        continue;
      }
      // u = fb + v (ft - fb), v = fl + u (fr - fl), solved together.
      const double du = ft[ui] - fb[ui];
      const double dv = fr[uj] - fl[uj];
      const double det = 1.0 - du * dv;
      const double u = (fb[ui] + fl[uj] * du) / det;
      const double v = (fl[uj] + fb[ui] * dv) / det;
      g(i, j) = (1 - v) * bottom[ui] + v * top[ui] + (1 - u) * left[uj] + u * right[uj] -
                ((1 - u) * (1 - v) * p00 + u * (1 - v) * p10 + u * v * p11 + (1 - u) * v * p01);
    }
  }
  return g;
}

namespace {

// Fractions of the lines of one family on one face: lines[a][b] is the
// fraction of point b along line a.
using LineFractions = std::vector<std::vector<double>>;

}  // namespace

void tfi_3d(Grid3& g) {
  const int ni = g.ni, nj = g.nj, nk = g.nk;
  auto fractions = [&](int lines, int points, auto point_of) {
    LineFractions out(static_cast<size_t>(lines));
    std::vector<Vec3> pts(static_cast<size_t>(points));
    for (int a = 0; a < lines; ++a) {
      for (int b = 0; b < points; ++b) pts[static_cast<size_t>(b)] = point_of(a, b);
      out[static_cast<size_t>(a)] = arc_fractions(pts);
    }
    return out;
  };
  // i-lines on faces j = 0, nj (indexed by k) and k = 0, nk (indexed by j).
  const auto ui_j0 = fractions(nk + 1, ni + 1, [&](int k, int i) { return g(i, 0, k); });
  const auto ui_jn = fractions(nk + 1, ni + 1, [&](int k, int i) { return g(i, nj, k); });
  const auto ui_k0 = fractions(nj + 1, ni + 1, [&](int j, int i) { return g(i, j, 0); });
  const auto ui_kn = fractions(nj + 1, ni + 1, [&](int j, int i) { return g(i, j, nk); });
  // j-lines on faces i = 0, ni (by k) and k = 0, nk (by i).
  const auto vj_i0 = fractions(nk + 1, nj + 1, [&](int k, int j) { return g(0, j, k); });
  const auto vj_in = fractions(nk + 1, nj + 1, [&](int k, int j) { return g(ni, j, k); });
  const auto vj_k0 = fractions(ni + 1, nj + 1, [&](int i, int j) { return g(i, j, 0); });
  const auto vj_kn = fractions(ni + 1, nj + 1, [&](int i, int j) { return g(i, j, nk); });
  // k-lines on faces i = 0, ni (by j) and j = 0, nj (by i).
  const auto wk_i0 = fractions(nj + 1, nk + 1, [&](int j, int k) { return g(0, j, k); });
  const auto wk_in = fractions(nj + 1, nk + 1, [&](int j, int k) { return g(ni, j, k); });
  const auto wk_j0 = fractions(ni + 1, nk + 1, [&](int i, int k) { return g(i, 0, k); });
  const auto wk_jn = fractions(ni + 1, nk + 1, [&](int i, int k) { return g(i, nj, k); });
  auto at = [](const LineFractions& f, int line, int point) {
    return f[static_cast<size_t>(line)][static_cast<size_t>(point)];
  };

  for (int k = 1; k < nk; ++k) {
    for (int j = 1; j < nj; ++j) {
      for (int i = 1; i < ni; ++i) {
        const double ti = static_cast<double>(i) / ni;
        const double tj = static_cast<double>(j) / nj;
        const double tk = static_cast<double>(k) / nk;
        const double u = 0.5 * ((1 - tj) * at(ui_j0, k, i) + tj * at(ui_jn, k, i) +
                                (1 - tk) * at(ui_k0, j, i) + tk * at(ui_kn, j, i));
        const double v = 0.5 * ((1 - ti) * at(vj_i0, k, j) + ti * at(vj_in, k, j) +
                                (1 - tk) * at(vj_k0, i, j) + tk * at(vj_kn, i, j));
        const double w = 0.5 * ((1 - ti) * at(wk_i0, j, k) + ti * at(wk_in, j, k) +
                                (1 - tj) * at(wk_j0, i, k) + tj * at(wk_jn, i, k));
        const double U[2] = {1 - u, u}, V[2] = {1 - v, v}, W[2] = {1 - w, w};
        const int I[2] = {0, ni}, J[2] = {0, nj}, K[2] = {0, nk};
        Vec3 x = Vec3::Zero();
        for (int a = 0; a < 2; ++a) {
          // Faces.
          x += U[a] * g(I[a], j, k) + V[a] * g(i, J[a], k) + W[a] * g(i, j, K[a]);
          for (int b = 0; b < 2; ++b) {
            // Edges.
            x -= V[a] * W[b] * g(i, J[a], K[b]) + U[a] * W[b] * g(I[a], j, K[b]) +
                 U[a] * V[b] * g(I[a], J[b], k);
            for (int c = 0; c < 2; ++c) x += U[a] * V[b] * W[c] * g(I[a], J[b], K[c]);  // corners
          }
        }
        g(i, j, k) = x;
      }
    }
  }
}

}  // namespace cooperage::mesh
