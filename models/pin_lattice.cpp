#include "models/pin_lattice.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tactip {

namespace {

// A pin of the planar layout before it is wrapped onto the dome (m).
struct Planar {
  int ring;
  double az;
  double x, y;
};

// Hexagonal lattice in axial coordinates (q, r); hex distance = ring.
std::vector<Planar> HexLayout(const SkinConfig& skin) {
  const double a = skin.pitch_mm * 1e-3;
  std::vector<Planar> pts;
  for (int q = -skin.rings; q <= skin.rings; ++q) {
    for (int r = -skin.rings; r <= skin.rings; ++r) {
      const int ring = std::max({std::abs(q), std::abs(r), std::abs(q + r)});
      if (ring > skin.rings) continue;
      const double x = a * (q + 0.5 * r);
      const double y = a * (std::sqrt(3.0) / 2.0 * r);
      double az = std::atan2(y, x);
      if (az < 0) az += 2.0 * std::numbers::pi;
      if (ring == 0) az = 0.0;
      pts.push_back({ring, az, x, y});
    }
  }
  return pts;
}

// Concentric rings k * spacing (k = 0..K) with pins_per_ring * k pins on ring k.
std::vector<Planar> RingLayout(const SkinConfig& skin) {
  const double s = skin.ridge_spacing_mm * 1e-3;
  const int K = static_cast<int>(std::floor(skin.pattern_radius_mm / skin.ridge_spacing_mm + 1e-9));
  std::vector<Planar> pts{{0, 0.0, 0.0, 0.0}};
  for (int k = 1; k <= K; ++k) {
    const int n = skin.pins_per_ring * k;
    for (int j = 0; j < n; ++j) {
      const double az = 2.0 * std::numbers::pi * j / n;
      pts.push_back({k, az, k * s * std::cos(az), k * s * std::sin(az)});
    }
  }
  return pts;
}

double Dist(const Planar& p, const Planar& q) { return std::hypot(p.x - q.x, p.y - q.y); }

// Wrap onto the dome: arc length from the apex equals the planar distance.
PinGeometry OnDome(const Planar& p, size_t i, double R) {
  const double rho = std::hypot(p.x, p.y);
  PinGeometry g;
  g.index = static_cast<int>(i);
  g.ring = p.ring;
  g.polar_rad = rho / R;
  g.azimuth_rad = p.az;
  g.normal = {std::cos(g.polar_rad), std::sin(g.polar_rad) * std::cos(g.azimuth_rad),
              std::sin(g.polar_rad) * std::sin(g.azimuth_rad)};
  return g;
}

// Neighbours: planar distance equal to the pitch `a`.
std::vector<std::array<int, 2>> HexNeighbours(const std::vector<Planar>& pts, double a) {
  std::vector<std::array<int, 2>> neighbours;
  for (size_t i = 0; i < pts.size(); ++i) {
    for (size_t j = i + 1; j < pts.size(); ++j) {
      if (std::abs(Dist(pts[i], pts[j]) - a) < 1e-6 * a) {
        neighbours.push_back({static_cast<int>(i), static_cast<int>(j)});
      }
    }
  }
  return neighbours;
}

// The first index of each ring of the sorted layout, closed by pts.size().
std::vector<size_t> RingStarts(const std::vector<Planar>& pts) {
  std::vector<size_t> first{0};
  for (size_t i = 1; i < pts.size(); ++i) {
    if (pts[i].ring != pts[i - 1].ring) first.push_back(i);
  }
  first.push_back(pts.size());
  return first;
}

// The edge between pins i and j, lower index first.
std::array<int, 2> Edge(size_t i, size_t j) {
  return {static_cast<int>(std::min(i, j)), static_cast<int>(std::max(i, j))};
}

// Consecutive pins along the ring [b, e), closing the ring (a ring of two pins has one edge).
void AddRingEdges(size_t b, size_t e, std::vector<std::array<int, 2>>& edges) {
  if (e - b >= 2) {
    for (size_t i = b; i < e; ++i) {
      const size_t j = (i + 1 < e) ? i + 1 : b;
      if (j != i && !(e - b == 2 && i == e - 1)) edges.push_back(Edge(i, j));
    }
  }
}

// Each pin of the ring [b, e) to its nearest pin on the ring [ib, ie) inside it, and to the
// second nearest too when almost as close.
void AddInwardEdges(const std::vector<Planar>& pts, size_t b, size_t e, size_t ib, size_t ie,
                    std::vector<std::array<int, 2>>& edges) {
  for (size_t i = b; i < e; ++i) {
    // The two nearest inner pins.
    size_t best = ib, second = ib;
    double d1 = 1e9, d2 = 1e9;
    for (size_t j = ib; j < ie; ++j) {
      const double d = Dist(pts[i], pts[j]);
      if (d < d1) {
        d2 = d1;
        second = best;
        d1 = d;
        best = j;
      } else if (d < d2) {
        d2 = d;
        second = j;
      }
    }
    edges.push_back(Edge(i, best));
    if (second != best && d2 < 1.25 * d1) edges.push_back(Edge(i, second));
  }
}

// Rings: consecutive pins along a ring, and each pin to its nearest pin(s) on the ring
// inside it (the second nearest too when almost as close), which triangulates the band.
std::vector<std::array<int, 2>> RingNeighbours(const std::vector<Planar>& pts) {
  std::vector<std::array<int, 2>> edges;
  const std::vector<size_t> first = RingStarts(pts);  // first index of each ring
  for (size_t k = 1; k + 1 < first.size(); ++k) {
    const size_t b = first[k], e = first[k + 1];  // ring k
    AddRingEdges(b, e, edges);
    AddInwardEdges(pts, b, e, first[k - 1], b, edges);
  }
  // Each edge once, in order.
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace

PinLattice PinLattice::Build(const SkinConfig& skin) {
  const double R = skin.radius_mm * 1e-3;
  // The planar layout, by ring, then azimuth.
  std::vector<Planar> pts = skin.Fingerprint() ? RingLayout(skin) : HexLayout(skin);
  std::sort(pts.begin(), pts.end(), [](const Planar& p, const Planar& q) {
    if (p.ring != q.ring) return p.ring < q.ring;
    return p.az < q.az;
  });
  // The pins on the dome, then the pairs the skin couples.
  PinLattice lat;
  for (size_t i = 0; i < pts.size(); ++i) lat.pins.push_back(OnDome(pts[i], i, R));
  lat.neighbours = skin.Fingerprint() ? RingNeighbours(pts) : HexNeighbours(pts, skin.pitch_mm * 1e-3);
  return lat;
}

}  // namespace tactip
