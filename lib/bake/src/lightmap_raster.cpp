#include "lightmap_raster.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace shpack::bake {
namespace {

struct Triangle {
  std::array<Vec3, 3> p;
  std::array<std::array<double, 2>, 3> t;  // texel space
  Vec3 normal;
  std::array<Vec3, 3> shading;  // the vertices' normals, or `normal` three times
  std::uint32_t shape = 0;
};

// Union-find with path halving.
struct Charts {
  std::vector<std::int32_t> parent;
  std::int32_t find(std::int32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void join(std::int32_t a, std::int32_t b) { parent[find(a)] = find(b); }
};

struct VertexKey {
  std::array<std::uint32_t, 5> bits;
  bool operator==(const VertexKey&) const = default;
};
struct VertexHash {
  std::size_t operator()(const VertexKey& k) const noexcept {
    std::uint64_t h = 1469598103934665603ull;
    for (const std::uint32_t b : k.bits) h = (h ^ b) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

std::string uv_text(double u, double v) {
  std::string text("(");  // built by appends: GCC 12 misreads "(" + std::string as overlapping (-Wrestrict)
  text.append(std::to_string(u)).append(", ").append(std::to_string(v)).append(")");
  return text;
}

using Polygon = std::vector<std::array<double, 2>>;

// Sutherland-Hodgman: the part of `in` with coordinate `axis` on the `keep_below` side of `at`.
Polygon clip(const Polygon& in, int axis, double at, bool keep_below) {
  Polygon out;
  const auto inside = [&](const std::array<double, 2>& q) { return keep_below ? q[axis] <= at : q[axis] >= at; };
  for (std::size_t i = 0; i < in.size(); ++i) {
    const auto& a = in[i];
    const auto& b = in[(i + 1) % in.size()];
    const bool ia = inside(a), ib = inside(b);
    if (ia) out.push_back(a);
    if (ia != ib) {
      const double s = (at - a[axis]) / (b[axis] - a[axis]);
      out.push_back({a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])});
    }
  }
  return out;
}

// Area and centroid of a simple polygon (the shoelace formula).
double polygon_area(const Polygon& q, std::array<double, 2>& centroid) {
  double a = 0, cx = 0, cy = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    const auto& p0 = q[i];
    const auto& p1 = q[(i + 1) % q.size()];
    const double cr = p0[0] * p1[1] - p1[0] * p0[1];
    a += cr;
    cx += (p0[0] + p1[0]) * cr;
    cy += (p0[1] + p1[1]) * cr;
  }
  if (std::fabs(a) > 0) centroid = {cx / (3.0 * a), cy / (3.0 * a)};
  return 0.5 * std::fabs(a);
}

// Barycentrics of x in the triangle's texel-space corners.
std::array<double, 3> barycentric(const Triangle& tri, double x, double y) {
  const auto& a = tri.t[0];
  const auto& b = tri.t[1];
  const auto& c = tri.t[2];
  const double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
  const double l1 = ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (y - a[1])) / det;
  const double l2 = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / det;
  return {1.0 - l1 - l2, l1, l2};
}

TexelPoint point_at(const Triangle& tri, const std::array<double, 3>& b) {
  Vec3 n = b[0] * tri.shading[0] + b[1] * tri.shading[1] + b[2] * tri.shading[2];
  if (dot(n, tri.normal) < 0) n = -1.0 * n;
  const double len = std::sqrt(dot(n, n));
  return {b[0] * tri.p[0] + b[1] * tri.p[1] + b[2] * tri.p[2], len > 1e-6 ? (1.0 / len) * n : tri.normal, tri.normal};
}

struct SubsampleOwner {
  std::int32_t triangle = -1;      // of the texel's chart
  std::int32_t strict_chart = -1;  // a chart that contains the centre strictly inside
  TexelPoint point;
};

// A clipped piece of one chart in one texel.
struct Piece {
  std::size_t texel = 0;
  std::int32_t chart = -1;
  double area = 0;
  std::uint32_t triangle = 0;
  std::array<double, 2> centroid{};
};

// Calls visit(i, j) for every texel the bounding box of the triangle's texel-space corners meets.
template <class Visit>
void for_each_texel(const Triangle& tri, std::uint32_t W, std::uint32_t H, const Visit& visit) {
  double x0 = tri.t[0][0], x1 = x0, y0 = tri.t[0][1], y1 = y0;
  for (const auto& c : tri.t) {
    x0 = std::min(x0, c[0]);
    x1 = std::max(x1, c[0]);
    y0 = std::min(y0, c[1]);
    y1 = std::max(y1, c[1]);
  }
  const auto lo = [](double a) { return static_cast<std::uint32_t>(std::max(0.0, std::floor(a))); };
  const std::uint32_t i1 = std::min(W - 1, static_cast<std::uint32_t>(std::floor(x1)));
  const std::uint32_t j1 = std::min(H - 1, static_cast<std::uint32_t>(std::floor(y1)));
  for (std::uint32_t j = lo(y0); j <= j1; ++j)
    for (std::uint32_t i = lo(x0); i <= i1; ++i) visit(i, j);
}

// Per texel, the chart whose pieces cover most of it (-1: none), and that chart's area.
std::vector<std::int32_t> texel_charts(std::vector<Piece>& pieces, std::size_t texels, std::vector<double>& area,
                                       std::uint64_t& shared) {
  std::stable_sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) {
    return a.texel != b.texel ? a.texel < b.texel : a.chart < b.chart;
  });
  std::vector<std::int32_t> chart(texels, -1);
  area.assign(texels, 0.0);
  shared = 0;
  for (std::size_t k = 0; k < pieces.size();) {
    const std::size_t texel = pieces[k].texel;
    int charts = 0;
    while (k < pieces.size() && pieces[k].texel == texel) {
      const std::int32_t c = pieces[k].chart;
      double sum = 0;
      for (; k < pieces.size() && pieces[k].texel == texel && pieces[k].chart == c; ++k) sum += pieces[k].area;
      ++charts;
      if (sum > area[texel]) {
        area[texel] = sum;
        chart[texel] = c;
      }
    }
    if (charts > 1) ++shared;
  }
  return chart;
}

struct Fallback {
  double area = 0;
  TexelPoint point;
};

}  // namespace

bool rasterize_lightmap(const scene::LightmapTarget& target, const std::vector<scene::SceneShape>& geometry,
                        LightmapRaster& out, std::string& error) {
  const std::uint32_t W = target.width, H = target.height;
  // The triangles, in texel space, with their charts.
  std::vector<Triangle> tris;
  std::vector<std::int32_t> vertex_of_corner;
  std::unordered_map<VertexKey, std::int32_t, VertexHash> welded;
  std::uint64_t degenerate = 0;
  for (const std::uint32_t s : target.shapes) {
    const scene::SceneShape& shape = geometry[s];
    const std::vector<float>& v = shape.vertices;
    const std::vector<float>& uv = shape.uv;
    for (std::size_t k = 0; 2 * k + 1 < uv.size(); ++k) {
      const float u = uv[2 * k], w = uv[2 * k + 1];
      if (!(u >= 0 && u <= 1 && w >= 0 && w <= 1)) {
        error = shape.label + ": vertex " + std::to_string(k) + "'s lightmap UV " + uv_text(u, w) +
                " is outside [0, 1]";
        return false;
      }
    }
    for (std::size_t t = 0; t + 2 < shape.indices.size(); t += 3) {
      Triangle tri;
      tri.shape = s;
      std::array<std::int32_t, 3> ids{};
      for (int c = 0; c < 3; ++c) {
        const std::uint32_t i = shape.indices[t + c];
        tri.p[c] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
        tri.t[c] = {uv[2 * i] * static_cast<double>(W), (1.0 - uv[2 * i + 1]) * static_cast<double>(H)};
        const VertexKey key{{std::bit_cast<std::uint32_t>(v[3 * i]), std::bit_cast<std::uint32_t>(v[3 * i + 1]),
                             std::bit_cast<std::uint32_t>(v[3 * i + 2]), std::bit_cast<std::uint32_t>(uv[2 * i]),
                             std::bit_cast<std::uint32_t>(uv[2 * i + 1])}};
        ids[c] = welded.emplace(key, static_cast<std::int32_t>(welded.size())).first->second;
      }
      const Vec3 n = cross(tri.p[1] - tri.p[0], tri.p[2] - tri.p[0]);
      const double len = std::sqrt(dot(n, n));
      const double uv_area = std::fabs((tri.t[1][0] - tri.t[0][0]) * (tri.t[2][1] - tri.t[0][1]) -
                                       (tri.t[2][0] - tri.t[0][0]) * (tri.t[1][1] - tri.t[0][1]));
      if (!(len > 0) || !(uv_area > 1e-12)) {
        ++degenerate;
        continue;
      }
      tri.normal = (1.0 / len) * n;
      for (int c = 0; c < 3; ++c) {
        const std::uint32_t i = shape.indices[t + c];
        tri.shading[c] = shape.normals.size() == v.size()
                             ? Vec3{shape.normals[3 * i], shape.normals[3 * i + 1], shape.normals[3 * i + 2]}
                             : tri.normal;
      }
      tris.push_back(tri);
      vertex_of_corner.insert(vertex_of_corner.end(), ids.begin(), ids.end());
    }
  }
  // Charts: triangles joined through their welded vertices.
  Charts charts;
  charts.parent.resize(welded.size());
  std::iota(charts.parent.begin(), charts.parent.end(), 0);
  for (std::size_t t = 0; t < tris.size(); ++t) {
    charts.join(vertex_of_corner[3 * t], vertex_of_corner[3 * t + 1]);
    charts.join(vertex_of_corner[3 * t], vertex_of_corner[3 * t + 2]);
  }
  const auto chart_of = [&](std::size_t t) { return charts.find(vertex_of_corner[3 * t]); };

  // Pass 1: every triangle clipped to every texel it meets. A texel belongs to the chart whose
  // pieces cover most of it, and only that chart's surface stands for it: two charts that meet
  // in one texel of the atlas are apart on the mesh, and their mean would be neither's light.
  const std::size_t texels = static_cast<std::size_t>(W) * H;
  std::vector<Piece> pieces;
  for (std::size_t t = 0; t < tris.size(); ++t)
    for_each_texel(tris[t], W, H, [&](std::uint32_t i, std::uint32_t j) {
      Polygon q{tris[t].t[0], tris[t].t[1], tris[t].t[2]};
      q = clip(clip(clip(clip(q, 0, i, false), 0, i + 1.0, true), 1, j, false), 1, j + 1.0, true);
      if (q.size() < 3) return;
      std::array<double, 2> centroid{};
      const double area = polygon_area(q, centroid);
      if (area > 0) pieces.push_back({std::size_t{j} * W + i, chart_of(t), area, static_cast<std::uint32_t>(t), centroid});
    });
  std::vector<double> area;
  out.width = W;
  out.height = H;
  out.chart = texel_charts(pieces, texels, area, out.shared);
  std::vector<Fallback> fallback(texels);  // the largest piece of the texel's chart
  for (const Piece& p : pieces)
    if (p.chart == out.chart[p.texel] && p.area > fallback[p.texel].area)
      fallback[p.texel] = {p.area, point_at(tris[p.triangle], barycentric(tris[p.triangle], p.centroid[0], p.centroid[1]))};
  pieces = {};

  // Pass 2: each sub-square centre is owned by the first triangle of the texel's chart that
  // contains it. Two charts containing one centre strictly inside overlap.
  constexpr int kSub = kSubsamples * kSubsamples;
  std::vector<SubsampleOwner> owners(texels * kSub);
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const Triangle& tri = tris[t];
    const std::int32_t chart = chart_of(t);
    bool overlap = false;
    for_each_texel(tri, W, H, [&](std::uint32_t i, std::uint32_t j) {
      const std::size_t texel = std::size_t{j} * W + i;
      if (overlap || out.chart[texel] < 0) return;
      for (int s = 0; s < kSub; ++s) {
        const double x = i + (s % kSubsamples + 0.5) / kSubsamples, y = j + (s / kSubsamples + 0.5) / kSubsamples;
        const std::array<double, 3> b = barycentric(tri, x, y);
        constexpr double kEdge = 1e-12;
        if (!(b[0] >= -kEdge && b[1] >= -kEdge && b[2] >= -kEdge)) continue;
        SubsampleOwner& o = owners[texel * kSub + s];
        if (b[0] > kEdge && b[1] > kEdge && b[2] > kEdge) {
          if (o.strict_chart >= 0 && o.strict_chart != chart) {
            error = geometry[tri.shape].label + ": its lightmap UVs overlap another chart at texel (" +
                    std::to_string(i) + ", " + std::to_string(j) + ") of " + target.label + "'s lightmap";
            overlap = true;
            return;
          }
          o.strict_chart = chart;
        }
        if (o.triangle < 0 && chart == out.chart[texel]) {
          o.triangle = static_cast<std::int32_t>(t);
          o.point = point_at(tri, b);
        }
      }
    });
    if (overlap) return false;
  }
  out.coverage.assign(texels, 0.0f);
  out.first.assign(texels + 1, 0);
  out.points.clear();
  for (std::size_t texel = 0; texel < texels; ++texel) {
    out.first[texel] = static_cast<std::uint32_t>(out.points.size());
    if (out.chart[texel] < 0) continue;
    out.coverage[texel] = static_cast<float>(std::min(1.0, area[texel]));
    for (int s = 0; s < kSub; ++s)
      if (owners[texel * kSub + s].triangle >= 0) out.points.push_back(owners[texel * kSub + s].point);
    if (out.points.size() == out.first[texel]) out.points.push_back(fallback[texel].point);
  }
  out.first[texels] = static_cast<std::uint32_t>(out.points.size());
  out.degenerate = degenerate;
  if (out.points.empty()) {
    error = target.label + ": no triangle with area covers a texel of its lightmap";
    return false;
  }
  return true;
}

}  // namespace shpack::bake
