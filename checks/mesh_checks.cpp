// CGAL checks of a sampled surface (the one translation unit of bezierpde that includes CGAL).
//
// Pipeline (see checks/mesh_checks.h for the contract):
//  1. validate the arrays (sizes, index range, finite coordinates);
//  2. merge coincident vertices: points closer than 1e-10 x (bounding-box diagonal) are one
//     vertex (seams of sampled closed surfaces, degenerate corners of sampled patches);
//  3. drop degenerate triangles: repeated vertex after merging, or three collinear points
//     (exact predicate of the Epick kernel);
//  4. self-intersections: the pairs of triangles whose closed bounding boxes overlap (a uniform grid
//     of cells, or CGAL::box_self_intersection_d where the grid would not pay; the same pairs), then
//     the exact tests of CGAL::Polygon_mesh_processing::self_intersections (same rules: a pair
//     sharing an edge intersects only when the two triangles are coplanar and overlap; a pair
//     sharing a vertex intersects when an opposite edge meets the other triangle), applied to the
//     merged triangle soup so that no halfedge structure (and no manifoldness) is needed;
//  5. closed: every undirected edge has exactly two triangles, traversed in opposite directions,
//     and the triangles around every vertex form one cycle;
//  6. volume: divergence formula (1/6) sum det(a - o, b - o, c - o) over the triangles (o the
//     bounding-box centre, to limit cancellation). For an open surface, every boundary loop must
//     be planar (max distance to its least-squares plane <= 1e-8 x the loop's diameter) and the
//     surface must be closed up to those loops; each loop is capped by a fan from its centroid,
//     whose contribution is -(1/3) <c - o, A> with A the loop's area vector.
//  7. cone volume: (1/6) sum det(a, b, c) over the input triangles, in input coordinates.
// Step 4 first tries the projection proof (checks/mesh_checks.h): one disk whose projection along
// a coordinate axis is injective has no self-intersection, and the pairwise tests are skipped.
#include "bezierpde/checks/mesh_checks.h"

#include "bezierpde/core/eigen.h"
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/Intersections_2/Segment_2_Segment_2.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "bezierpde/core/errors.h"

namespace bpde {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
using Tri = std::array<int, 3>;

// ------------------------------------------------------------------ merging
int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

/// Union of the points closer than tol (spatial hash). Only points inside the box [lo, hi]
/// (the referenced vertices' bounding box) take part; the others stay alone. Returns for each
/// input vertex the index of its representative (the smallest index of its cluster).
/// `step(fraction)` is called as the points are done (every 1/50 of them).
template <class Step>
std::vector<int> merge_coincident(const std::vector<Eigen::Vector3d>& p, double tol, const Eigen::Vector3d& lo,
                                  const Eigen::Vector3d& hi, Step step) {
  const int n = static_cast<int>(p.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  if (n == 0) return parent;
  if (!(tol > 0)) {
    // All points coincide exactly or the mesh is a single point: merge exact duplicates only.
    tol = 0;
  }
  // Cells of size 2 tol: a point within tol of x lies in x's cell or, along each axis, in the
  // neighbour on the side of the nearer cell face, so 8 cells are searched.
  const double cell = 2 * tol;
  struct CellHash {
    std::size_t operator()(const std::array<std::int64_t, 3>& c) const {
      std::size_t h = static_cast<std::size_t>(c[0]) * 73856093u;
      h ^= static_cast<std::size_t>(c[1]) * 19349663u;
      h ^= static_cast<std::size_t>(c[2]) * 83492791u;
      return h;
    }
  };
  // cell -> last point inserted in it (open addressing: a power-of-2 table of at least twice the
  // points, linear probing); next_in_cell chains the others
  using Key = std::array<std::int64_t, 3>;
  std::size_t slots = 16;
  while (slots < 2 * static_cast<std::size_t>(n)) slots *= 2;
  std::vector<Key> keys(slots);
  std::vector<int> head(slots, -1);
  auto slot_of = [&](const Key& key) {
    std::size_t at = (CellHash{}(key) * 0x9e3779b97f4a7c15ull) >> 20 & (slots - 1);
    while (head[at] >= 0 && (keys[at][0] != key[0] || keys[at][1] != key[1] || keys[at][2] != key[2]))
      at = (at + 1) & (slots - 1);
    return at;  // the key's slot, or the empty slot where it goes
  };
  std::vector<int> next_in_cell(n, -1);
  const double tol2 = tol * tol;
  const int every = std::max(1, n / 50);
  for (int i = 0; i < n; ++i) {
    if (i % every == 0 && i > 0) step(static_cast<double>(i) / n);
    if ((p[i].array() < lo.array()).any() || (p[i].array() > hi.array()).any()) continue;
    Key c{0, 0, 0}, side{0, 0, 0};
    if (cell > 0)
      for (int a = 0; a < 3; ++a) {
        // (p - lo) / cell <= diagonal / (2e-10 diagonal): no overflow of the cell index
        const double q = (p[i][a] - lo[a]) / cell, f = std::floor(q);
        c[a] = static_cast<std::int64_t>(f);
        side[a] = q - f < 0.5 ? -1 : 1;
      }
    for (int mask = 0; mask < 8; ++mask) {
      if (cell == 0 && mask) break;
      const Key key{c[0] + ((mask & 1) ? side[0] : 0), c[1] + ((mask & 2) ? side[1] : 0),
                    c[2] + ((mask & 4) ? side[2] : 0)};
      for (int j = head[slot_of(key)]; j >= 0; j = next_in_cell[j]) {
        if ((p[i] - p[j]).squaredNorm() <= tol2) {
          const int ri = find_root(parent, i), rj = find_root(parent, j);
          if (ri != rj) parent[std::max(ri, rj)] = std::min(ri, rj);
        }
      }
    }
    const std::size_t at = slot_of(c);
    next_in_cell[i] = head[at];
    keys[at] = c;
    head[at] = i;
  }
  std::vector<int> rep(n);
  for (int i = 0; i < n; ++i) rep[i] = find_root(parent, i);
  return rep;
}

// ------------------------------------------------------------------ self-intersections
/// Exact test of CGAL::Polygon_mesh_processing::internal::do_faces_intersect, on a soup.
bool faces_intersect(const Tri& h, const Tri& g, const std::vector<Point>& P) {
  int shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (h[i] == g[j]) ++shared;
  if (shared == 3) return true;  // the same triangle twice: they overlap
  if (shared == 2) {
    // shared edge (p, q); r and s the third vertices
    int r = -1, s = -1;
    for (int i = 0; i < 3; ++i)
      if (h[i] != g[0] && h[i] != g[1] && h[i] != g[2]) r = h[i];
    for (int j = 0; j < 3; ++j)
      if (g[j] != h[0] && g[j] != h[1] && g[j] != h[2]) s = g[j];
    int pq[2], k = 0;
    for (int i = 0; i < 3; ++i)
      if (h[i] != r) pq[k++] = h[i];
    const Point &p = P[pq[0]], &q = P[pq[1]], &pr = P[r], &ps = P[s];
    return CGAL::coplanar(p, q, pr, ps) && CGAL::coplanar_orientation(p, q, pr, ps) == CGAL::POSITIVE;
  }
  const Triangle th(P[h[0]], P[h[1]], P[h[2]]);
  const Triangle tg(P[g[0]], P[g[1]], P[g[2]]);
  if (shared == 1) {
    int i = 0, j = 0;
    for (i = 0; i < 3; ++i) {
      bool found = false;
      for (j = 0; j < 3; ++j)
        if (h[i] == g[j]) {
          found = true;
          break;
        }
      if (found) break;
    }
    // When the far edge of g lies strictly on one side of the plane of h, g meets that plane in v
    // alone, so neither test below can succeed (the far edge of h lies in the plane and misses v);
    // likewise with h and g exchanged. These exact orientations (the first ones do_intersect would
    // compute) decide most vertex-sharing pairs of a smooth surface at a third of the cost.
    const Point &v = P[h[i]], &h1 = P[h[(i + 1) % 3]], &h2 = P[h[(i + 2) % 3]];
    const Point &g1 = P[g[(j + 1) % 3]], &g2 = P[g[(j + 2) % 3]];
    auto one_side = [](const Point& a, const Point& b, const Point& c, const Point& p, const Point& q) {
      const CGAL::Orientation op = CGAL::orientation(a, b, c, p);
      return op != CGAL::COPLANAR && op == CGAL::orientation(a, b, c, q);
    };
    if (one_side(v, h1, h2, g1, g2) || one_side(v, g1, g2, h1, h2)) return false;
    return CGAL::do_intersect(th, Segment(g1, g2)) || CGAL::do_intersect(tg, Segment(h1, h2));
  }
  return CGAL::do_intersect(th, tg);
}

using Bbox = CGAL::Bbox_3;

/// Closed overlap of two boxes (the CLOSED topology of CGAL::box_self_intersection_d).
bool boxes_overlap(const Bbox& a, const Bbox& b) {
  return a.xmin() <= b.xmax() && b.xmin() <= a.xmax() && a.ymin() <= b.ymax() && b.ymin() <= a.ymax() &&
         a.zmin() <= b.zmax() && b.zmin() <= a.zmax();
}

/// The reference broad phase: every pair of triangles whose closed bounding boxes overlap, by
/// CGAL::box_self_intersection_d; f(a, b) is called once per pair.
template <class F>
void overlapping_pairs_cgal(const std::vector<Bbox>& bb, F f) {
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int, CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS>;
  std::vector<Box> boxes;
  boxes.reserve(bb.size());
  for (std::size_t i = 0; i < bb.size(); ++i) boxes.emplace_back(bb[i], static_cast<int>(i));
  std::vector<const Box*> ptr;
  ptr.reserve(boxes.size());
  for (const Box& b : boxes) ptr.push_back(&b);
  auto callback = [&](const Box* a, const Box* b) { f(a->info(), b->info()); };
  CGAL::box_self_intersection_d<CGAL::Sequential_tag>(ptr.begin(), ptr.end(), callback);
}

/// The same pairs by a uniform grid (the sampled meshes are surfaces of nearly uniform triangles):
/// cells of twice the mean largest box extent (measured on the sampled jobs: fewer listings than
/// the mean extent for as many box tests), every box listed in the cells it meets, and a pair of
/// overlapping boxes reported only in the cell of the low corner of their intersection, which both
/// boxes meet (floor((x - origin) / h) is monotone in x), so exactly once. Returns false without
/// calling f when the grid would not pay (a few boxes spanning many cells, or crowded cells): the
/// caller then takes overlapping_pairs_cgal.
// `step(fraction)` is called once the boxes are listed (0) and as the cells are done (about every
// 1/100 of the listings).
template <class F, class Step>
bool overlapping_pairs_grid(const std::vector<Bbox>& bb, F f, Step step) {
  const std::size_t nb = bb.size();
  if (nb < 2) return true;
  double lo[3] = {bb[0].xmin(), bb[0].ymin(), bb[0].zmin()}, ext = 0;
  for (const Bbox& b : bb) {
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], b.min(a));
    ext += std::max({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()});
  }
  const double h = 2 * ext / static_cast<double>(nb);
  if (!(h > 0) || !std::isfinite(h)) return false;
  constexpr std::int64_t kMaxCells = std::int64_t{1} << 20;  // per axis
  auto cell = [&](double x, int a) {
    const double q = std::floor((x - lo[a]) / h);
    return q < static_cast<double>(kMaxCells) ? static_cast<std::int64_t>(q) : kMaxCells;
  };
  // cell ranges per box and the grid's extent; give up when a box meets more than 64 cells or the
  // listings exceed 16 per box
  std::vector<std::array<std::int32_t, 6>> range(nb);
  std::int64_t dims[3] = {1, 1, 1}, incidences = 0;
  for (std::size_t i = 0; i < nb; ++i) {
    std::int64_t count = 1;
    for (int a = 0; a < 3; ++a) {
      const std::int64_t c0 = cell(bb[i].min(a), a), c1 = cell(bb[i].max(a), a);
      if (c1 >= kMaxCells) return false;
      range[i][a] = static_cast<std::int32_t>(c0);
      range[i][3 + a] = static_cast<std::int32_t>(c1);
      dims[a] = std::max(dims[a], c1 + 1);
      count *= c1 - c0 + 1;
    }
    if (count > 64) return false;
    incidences += count;
  }
  if (incidences > 16 * static_cast<std::int64_t>(nb)) return false;
  // listings sorted by cell: counting sort over the dense grid when it is small, else a sort of keys
  const std::int64_t ncells = dims[0] * dims[1] * dims[2];
  auto key = [&](std::int64_t x, std::int64_t y, std::int64_t z) { return (z * dims[1] + y) * dims[0] + x; };
  std::vector<std::pair<std::int64_t, int>> list;
  list.reserve(static_cast<std::size_t>(incidences));
  for (std::size_t i = 0; i < nb; ++i) {
    const auto& r = range[i];
    for (std::int64_t z = r[2]; z <= r[5]; ++z)
      for (std::int64_t y = r[1]; y <= r[4]; ++y)
        for (std::int64_t x = r[0]; x <= r[3]; ++x) list.emplace_back(key(x, y, z), static_cast<int>(i));
  }
  if (ncells <= 16 * incidences) {
    std::vector<int> start(static_cast<std::size_t>(ncells) + 1, 0);
    for (const auto& [k, i] : list) ++start[static_cast<std::size_t>(k) + 1];
    for (std::int64_t c = 0; c < ncells; ++c) start[c + 1] += start[c];
    std::vector<std::pair<std::int64_t, int>> sorted(list.size());
    for (const auto& e : list) sorted[static_cast<std::size_t>(start[static_cast<std::size_t>(e.first)]++)] = e;
    list.swap(sorted);
  } else {
    std::sort(list.begin(), list.end());
  }
  // crowded cells (many boxes that need not overlap) would make the cell pairs quadratic
  std::int64_t pair_tests = 0;
  for (std::size_t s = 0, e = 0; s < list.size(); s = e) {
    for (e = s + 1; e < list.size() && list[e].first == list[s].first;) ++e;
    pair_tests += static_cast<std::int64_t>(e - s) * static_cast<std::int64_t>(e - s - 1) / 2;
  }
  if (pair_tests > 64 * static_cast<std::int64_t>(nb)) return false;
  const std::size_t every = std::max<std::size_t>(1, list.size() / 100);
  std::size_t next_step = every;
  step(0.0);  // listed
  for (std::size_t s = 0, e = 0; s < list.size(); s = e) {
    for (e = s + 1; e < list.size() && list[e].first == list[s].first;) ++e;
    if (e >= next_step) {
      step(static_cast<double>(e) / static_cast<double>(list.size()));
      next_step = e + every;
    }
    const std::int64_t here = list[s].first;
    for (std::size_t p = s; p < e; ++p)
      for (std::size_t q = p + 1; q < e; ++q) {
        const int i = list[p].second, j = list[q].second;
        const Bbox &a = bb[static_cast<std::size_t>(i)], &b = bb[static_cast<std::size_t>(j)];
        if (!boxes_overlap(a, b)) continue;
        const auto &ra = range[static_cast<std::size_t>(i)], &rb = range[static_cast<std::size_t>(j)];
        if (key(std::max(ra[0], rb[0]), std::max(ra[1], rb[1]), std::max(ra[2], rb[2])) == here) f(i, j);
      }
  }
  return true;
}

/// Number of intersecting pairs (clamped to int) and of box pairs tested. `step(fraction)` as in
/// overlapping_pairs_grid (not called by the CGAL broad phase).
template <class Step>
std::pair<int, long long> count_self_intersections(const std::vector<Tri>& tris, const std::vector<Point>& P,
                                                   BroadPhase broad_phase, Step step) {
  std::vector<Bbox> bb;
  bb.reserve(tris.size());
  for (const auto& t : tris) bb.push_back(P[t[0]].bbox() + P[t[1]].bbox() + P[t[2]].bbox());
  long long count = 0, pairs = 0;
  auto test = [&](int a, int b) {
    ++pairs;
    if (faces_intersect(tris[static_cast<std::size_t>(a)], tris[static_cast<std::size_t>(b)], P)) ++count;
  };
  if (broad_phase == BroadPhase::kCgalBoxes || !overlapping_pairs_grid(bb, test, step)) overlapping_pairs_cgal(bb, test);
  return {static_cast<int>(std::min<long long>(count, std::numeric_limits<int>::max())), pairs};
}

// ------------------------------------------------------------------ topology
using Edge = std::pair<int, int>;

/// Directed-edge multiplicities of the soup, one entry per undirected edge {a < b}: how many
/// triangles run a -> b (forward) and b -> a (backward). One sort of keys (a << 32 | b) << 1 | dir,
/// and no lookup of reverse edges afterwards.
struct EdgeMap {
  struct Entry {
    int a, b;          ///< a < b
    int forward = 0;   ///< multiplicity of a -> b
    int backward = 0;  ///< multiplicity of b -> a
  };
  std::vector<Entry> edges;
};

EdgeMap directed_edges(const std::vector<Tri>& tris, int num_vertices) {
  // the keys sorted: a counting sort by the low vertex, then each (short) run by insertion
  std::vector<int> start(static_cast<std::size_t>(num_vertices) + 1, 0);
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) ++start[static_cast<std::size_t>(std::min(t[k], t[(k + 1) % 3])) + 1];
  for (int v = 0; v < num_vertices; ++v) start[v + 1] += start[v];
  std::vector<std::uint64_t> all(tris.size() * 3);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const auto lo = static_cast<std::uint32_t>(std::min(a, b)), hi = static_cast<std::uint32_t>(std::max(a, b));
      all[static_cast<std::size_t>(fill[lo]++)] = ((static_cast<std::uint64_t>(lo) << 32 | hi) << 1) | (a > b ? 1u : 0u);
    }
  for (int v = 0; v < num_vertices; ++v) {
    const auto first = all.begin() + start[v], last = all.begin() + start[v + 1];
    if (last - first <= 16) {
      for (auto i = first + 1; i < last; ++i)
        for (auto j = i; j > first && *(j - 1) > *j; --j) std::iter_swap(j - 1, j);
    } else {
      std::sort(first, last);
    }
  }
  EdgeMap e;
  e.edges.reserve(all.size() / 2 + 1);
  for (std::size_t s = 0, f = 0; s < all.size(); s = f) {
    const std::uint64_t undirected = all[s] >> 1;
    EdgeMap::Entry entry{static_cast<int>(undirected >> 32), static_cast<int>(undirected & 0xffffffffu)};
    for (f = s; f < all.size() && (all[f] >> 1) == undirected; ++f) ++((all[f] & 1u) ? entry.backward : entry.forward);
    e.edges.push_back(entry);
  }
  return e;
}

/// Every undirected edge has exactly two triangles, in opposite directions, and every vertex's
/// link is one cycle.
bool is_closed_manifold(const std::vector<Tri>& tris, const EdgeMap& de, int num_vertices) {
  if (tris.empty()) return false;
  for (const auto& e : de.edges)
    if (e.forward != 1 || e.backward != 1) return false;
  // vertex links: at vertex a of triangle (a, b, c), the link edge b -> c (CSR by vertex).
  std::vector<int> start(num_vertices + 1, 0);
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) ++start[t[k] + 1];
  for (int v = 0; v < num_vertices; ++v) start[v + 1] += start[v];
  std::vector<Edge> link(start.back());
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) link[fill[t[k]]++] = {t[(k + 1) % 3], t[(k + 2) % 3]};
  for (int v = 0; v < num_vertices; ++v) {
    const int lo = start[v], hi = start[v + 1];
    if (lo == hi) continue;  // unreferenced vertex
    std::sort(link.begin() + lo, link.begin() + hi);
    for (int e = lo + 1; e < hi; ++e)
      if (link[e].first == link[e - 1].first) return false;  // two link edges leave b
    auto next = [&](int b) {
      auto it = std::lower_bound(link.begin() + lo, link.begin() + hi, Edge{b, -1});
      return (it != link.begin() + hi && it->first == b) ? it->second : -1;
    };
    const int first = link[lo].first;
    int cur = first, steps = 0;
    do {
      cur = next(cur);
      if (cur < 0) return false;
      ++steps;
    } while (cur != first && steps <= hi - lo);
    if (cur != first || steps != hi - lo) return false;  // one cycle through every link edge
  }
  return true;
}

// ------------------------------------------------------------------ projection proof
using Point2 = Kernel::Point_2;
using Segment2 = Kernel::Segment_2;

/// The one loop of the algebraic boundary of the soup (the directed edges of net multiplicity
/// +1, followed from vertex to vertex), or empty when an edge has multiplicity beyond +-1, a
/// vertex has more than one boundary edge out or in, or the boundary edges are not one loop.
std::vector<int> single_boundary_loop(const EdgeMap& de, int num_vertices) {
  std::vector<int> next(static_cast<std::size_t>(num_vertices), -1), in(static_cast<std::size_t>(num_vertices), 0);
  std::size_t edges = 0;
  int first = -1;
  for (const auto& e : de.edges) {
    const int net = e.forward - e.backward;
    if (net == 0) continue;
    if (net > 1 || net < -1) return {};
    const int from = net > 0 ? e.a : e.b, to = net > 0 ? e.b : e.a;
    if (next[static_cast<std::size_t>(from)] >= 0 || in[static_cast<std::size_t>(to)]++ > 0) return {};
    next[static_cast<std::size_t>(from)] = to;
    if (first < 0) first = from;
    ++edges;
  }
  if (edges < 3) return {};
  std::vector<int> loop;
  loop.reserve(edges);
  int v = first;
  do {
    loop.push_back(v);
    v = next[static_cast<std::size_t>(v)];
  } while (v >= 0 && v != first && loop.size() <= edges);
  if (v != first || loop.size() != edges) return {};
  return loop;
}

/// The closed polygon q[0], q[1], ..., q[m-1] is simple (exact predicates): its points are
/// distinct, adjacent segments meet only at their common point, non-adjacent ones not at all.
bool simple_polygon(const std::vector<Point2>& q) {
  const std::size_t m = q.size();
  std::vector<Point2> sorted(q);
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
  for (std::size_t i = 0; i < m; ++i) {
    const Point2 &a = q[(i + m - 1) % m], &b = q[i], &c = q[(i + 1) % m];
    if (CGAL::collinear(a, b, c) && !CGAL::collinear_are_strictly_ordered_along_line(a, b, c)) return false;
  }
  // non-adjacent segments: a sweep over the segments sorted by their smallest x
  struct Seg {
    double x0, x1, y0, y1;
    std::size_t i;
  };
  std::vector<Seg> seg(m);
  for (std::size_t i = 0; i < m; ++i) {
    const Point2 &a = q[i], &b = q[(i + 1) % m];
    seg[i] = {std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()), std::max(a.y(), b.y()), i};
  }
  std::sort(seg.begin(), seg.end(), [](const Seg& s, const Seg& t) { return s.x0 < t.x0; });
  for (std::size_t s = 0; s < m; ++s)
    for (std::size_t t = s + 1; t < m && seg[t].x0 <= seg[s].x1; ++t) {
      const std::size_t i = seg[s].i, j = seg[t].i, d = i > j ? i - j : j - i;
      if (d == 1 || d == m - 1) continue;  // adjacent: checked above
      if (seg[t].y0 > seg[s].y1 || seg[s].y0 > seg[t].y1) continue;
      if (CGAL::do_intersect(Segment2(q[i], q[(i + 1) % m]), Segment2(q[j], q[(j + 1) % m]))) return false;
    }
  return true;
}

/// The projection proof of checks/mesh_checks.h: true when the soup is one disk whose projection
/// along one coordinate axis is injective (hence no two triangles intersect).
bool embedded_by_projection(const std::vector<Tri>& tris, const std::vector<Point>& P, const EdgeMap& de) {
  if (tris.empty()) return false;
  const std::vector<int> loop = single_boundary_loop(de, static_cast<int>(P.size()));
  if (loop.empty()) return false;
  Eigen::Vector3d area = Eigen::Vector3d::Zero();
  auto at = [&](int v) { return Eigen::Vector3d(P[v].x(), P[v].y(), P[v].z()); };
  for (const auto& t : tris) area += (at(t[1]) - at(t[0])).cross(at(t[2]) - at(t[0]));
  std::array<int, 3> axes{0, 1, 2};
  std::sort(axes.begin(), axes.end(), [&](int a, int b) { return std::abs(area[a]) > std::abs(area[b]); });
  for (int k : axes) {
    if (!(std::abs(area[k]) > 0)) break;
    auto q = [&](int v) { return Point2(P[v][(k + 1) % 3], P[v][(k + 2) % 3]); };
    const CGAL::Orientation expected = area[k] > 0 ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN;
    bool ok = true;
    for (const auto& t : tris)
      if (CGAL::orientation(q(t[0]), q(t[1]), q(t[2])) != expected) {
        ok = false;
        break;
      }
    if (!ok) continue;
    std::vector<Point2> polygon;
    polygon.reserve(loop.size());
    for (int v : loop) polygon.push_back(q(v));
    if (simple_polygon(polygon)) return true;
  }
  return false;
}

double det3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) { return a.dot(b.cross(c)); }

/// Volume of the soup closed by planar caps over its boundary loops, or empty when the boundary
/// is not a set of disjoint planar loops or the soup is not closed up to them.
std::optional<double> capped_volume(const std::vector<Tri>& tris, const EdgeMap& de,
                                    const std::vector<Eigen::Vector3d>& X, const Eigen::Vector3d& o, bool closed) {
  if (tris.empty()) return std::nullopt;
  double vol = 0;
  for (const auto& t : tris) vol += det3(X[t[0]] - o, X[t[1]] - o, X[t[2]] - o);
  vol /= 6.0;
  if (closed) return vol;

  // Boundary: directed edges a -> b whose reverse is missing. Interior edges must pair up.
  std::unordered_map<int, int> out;  // boundary successor
  bool ok = true;
  for (const auto& e : de.edges) {
    if (e.forward + e.backward == 1) {  // one direction, once: a boundary edge
      const auto [from, to] = e.forward ? std::pair{e.a, e.b} : std::pair{e.b, e.a};
      if (!out.emplace(from, to).second) ok = false;  // pinched boundary vertex
    } else if (e.forward != 1 || e.backward != 1) {
      ok = false;  // non-manifold or inconsistently oriented edge
    }
  }
  if (!ok || out.empty()) return std::nullopt;  // (empty: closed as a chain, not a manifold)
  // deterministic loop order (the sum does not depend on it beyond rounding)
  std::vector<int> starts;
  starts.reserve(out.size());
  for (const auto& [a, b] : out) starts.push_back(a);
  std::sort(starts.begin(), starts.end());
  std::unordered_map<int, bool> used;
  for (int start : starts) {
    if (used[start]) continue;
    std::vector<int> loop;
    int cur = start;
    do {
      if (used[cur]) return std::nullopt;
      used[cur] = true;
      loop.push_back(cur);
      auto it = out.find(cur);
      if (it == out.end()) return std::nullopt;
      cur = it->second;
    } while (cur != start && loop.size() <= out.size());
    if (cur != start) return std::nullopt;
    // least-squares plane of the loop
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v : loop) c += X[v] - o;
    c /= static_cast<double>(loop.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    double diam = 0;
    for (int v : loop) {
      const Eigen::Vector3d d = X[v] - o - c;
      cov += d * d.transpose();
      diam = std::max(diam, 2 * d.norm());
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
    const Eigen::Vector3d n = es.eigenvectors().col(0);
    double dev = 0;
    for (int v : loop) dev = std::max(dev, std::abs((X[v] - o - c).dot(n)));
    if (dev > 1e-8 * diam) return std::nullopt;
    // area vector of the loop (the surface runs loop[i] -> loop[i+1]; the cap runs backwards)
    Eigen::Vector3d A = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < loop.size(); ++i)
      A += (X[loop[i]] - o - c).cross(X[loop[(i + 1) % loop.size()]] - o - c);
    A *= 0.5;
    vol -= c.dot(A) / 3.0;
  }
  return vol;
}

}  // namespace

MeshCheckReport check_mesh(const std::vector<double>& vertices, const std::vector<int>& triangles,
                           const MeshCheckOptions& options) {
  if (vertices.size() % 3 != 0)
    throw SizeError("mesh check: vertices has " + std::to_string(vertices.size()) + " numbers, not a multiple of 3");
  if (triangles.size() % 3 != 0)
    throw SizeError("mesh check: triangles has " + std::to_string(triangles.size()) + " indices, not a multiple of 3");
  const int nv = static_cast<int>(vertices.size() / 3);
  for (std::size_t i = 0; i < vertices.size(); ++i)
    if (!std::isfinite(vertices[i]))
      throw NonFiniteError("mesh check: vertex " + std::to_string(i / 3) + " coordinate " + std::to_string(i % 3) +
                           " is not finite");
  for (std::size_t i = 0; i < triangles.size(); ++i)
    if (triangles[i] < 0 || triangles[i] >= nv)
      throw SizeError("mesh check: triangle " + std::to_string(i / 3) + " index " + std::to_string(triangles[i]) +
                      " is out of range [0, " + std::to_string(nv) + ")");

  // Progress: the fractions at the ends of the phases, after their times on a sampled sphere of
  // 2.6e6 triangles (measured, 12 s: the merge of coincident vertices 31%, the triangles 6%, the
  // grid's listing 13%, the exact tests of the pairs 31%, the closedness 18%, the capped volume 1%).
  constexpr double kMergeFrom = 0.02, kMerged = 0.31, kPairsFrom = 0.37, kListed = 0.5, kPairsTo = 0.81, kClosed = 0.99;
  auto progress = [&options](double f) { bpde::report(options.progress, kMeshCheckStage, f, 1.0); };
  progress(0.0);
  MeshCheckReport report;
  const std::size_t nf = triangles.size() / 3;
  std::vector<Eigen::Vector3d> X(nv);
  for (int i = 0; i < nv; ++i) X[i] = {vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]};

  // cone volume on the input
  long double cone = 0;
  for (std::size_t f = 0; f < nf; ++f)
    cone += det3(X[triangles[3 * f]], X[triangles[3 * f + 1]], X[triangles[3 * f + 2]]);
  report.cone_volume = static_cast<double>(cone / 6.0L);
  if (!std::isfinite(report.cone_volume))
    throw NonFiniteError("mesh check: the cone volume overflows (coordinates too large)");
  report.merged_vertices = nv;
  if (nf == 0) return report;

  // bounding box of the referenced vertices
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (int idx : triangles) {
    lo = lo.cwiseMin(X[idx]);
    hi = hi.cwiseMax(X[idx]);
  }
  const Eigen::Vector3d o = 0.5 * (lo + hi);
  const double diag = (hi - lo).norm();
  if (!std::isfinite(diag))
    throw NonFiniteError("mesh check: the vertex coordinates overflow (bounding box not finite)");

  progress(kMergeFrom);
  const std::vector<int> rep =
      merge_coincident(X, 1e-10 * diag, lo, hi, [&](double f) { progress(kMergeFrom + f * (kMerged - kMergeFrom)); });
  // compact the representatives
  std::vector<int> newid(nv, -1);
  int nm = 0;
  std::vector<Point> P;
  std::vector<Eigen::Vector3d> Y;
  for (int i = 0; i < nv; ++i)
    if (rep[i] == i) {
      newid[i] = nm++;
      P.emplace_back(X[i][0], X[i][1], X[i][2]);
      Y.push_back(X[i]);
    }
  report.merged_vertices = nm;
  progress(kMerged);

  std::vector<Tri> tris;
  tris.reserve(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    Tri t{newid[rep[triangles[3 * f]]], newid[rep[triangles[3 * f + 1]]], newid[rep[triangles[3 * f + 2]]]};
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || CGAL::collinear(P[t[0]], P[t[1]], P[t[2]])) {
      ++report.degenerate_triangles;
      continue;
    }
    tris.push_back(t);
  }

  progress(kPairsFrom);
  const auto de = directed_edges(tris, nm);
  report.embedded_by_projection = options.projection_proof && embedded_by_projection(tris, P, de);
  if (!report.embedded_by_projection)
    std::tie(report.self_intersections, report.box_pairs) = count_self_intersections(
        tris, P, options.broad_phase, [&](double f) { progress(kListed + f * (kPairsTo - kListed)); });
  progress(kPairsTo);
  report.closed = is_closed_manifold(tris, de, nm);
  progress(kClosed);
  report.volume = capped_volume(tris, de, Y, o, report.closed);
  if (report.volume && !std::isfinite(*report.volume))
    throw NonFiniteError("mesh check: the enclosed volume overflows (coordinates too large)");
  return report;
}

}  // namespace bpde
