#include "analytic_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "cadmedial/ball_tree.hpp"

namespace cadmedial::testing {

namespace {

double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// Root of a function decreasing on [lo, hi] with f(lo) >= 0 >= f(hi), by
// bisection down to the resolution of doubles.
template <class F>
double bisect(F f, double lo, double hi) {
  for (int i = 0; i < 400; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (f(mid) >= 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Distance from (y0, y1) (both >= 0) to the ellipse x²/e0² + y²/e1² = 1, e0 >= e1.
double ellipseCurveDistance(double e0, double e1, double y0, double y1) {
  double x0, x1;
  if (y1 > 0) {
    auto g = [&](double t) {
      const double a = e0 * y0 / (t + e0 * e0), b = e1 * y1 / (t + e1 * e1);
      return a * a + b * b - 1;
    };
    const double t = bisect(g, -e1 * e1 + e1 * y1, -e1 * e1 + std::hypot(e0 * y0, e1 * y1));
    x0 = e0 * e0 * y0 / (t + e0 * e0);
    x1 = e1 * e1 * y1 / (t + e1 * e1);
  } else if (e0 > e1 && y0 < (e0 * e0 - e1 * e1) / e0) {
    x0 = e0 * e0 * y0 / (e0 * e0 - e1 * e1);
    x1 = e1 * std::sqrt(std::max(0.0, 1 - (x0 / e0) * (x0 / e0)));
  } else {
    x0 = e0;
    x1 = 0;
  }
  return std::hypot(x0 - y0, x1 - y1);
}

class Sphere : public AnalyticShape {
 public:
  explicit Sphere(double r) : r_(r) {}
  std::string name() const override { return "sphere"; }
  double surfaceArea() const override { return 4 * M_PI * r_ * r_; }
  double diagonal() const override { return 2 * std::sqrt(3.0) * r_; }
  bool inside(const Vec3& p) const override { return norm(p) < r_; }
  double surfaceDistance(const Vec3& p) const override { return std::abs(norm(p) - r_); }
  double innerAxisDistance(const Vec3& p) const override { return norm(p); }
  double wholeAxisDistance(const Vec3& p) const override { return norm(p); }
  Vec3 randomSurfacePoint(std::mt19937& rng) const override {
    std::normal_distribution<double> g;
    Vec3 v{g(rng), g(rng), g(rng)};
    const double l = norm(v);
    return {r_ * v[0] / l, r_ * v[1] / l, r_ * v[2] / l};
  }

 private:
  double r_;
};

class Ellipsoid : public AnalyticShape {
 public:
  Ellipsoid(double a, double b, double c) : e_{a, b, c}, A_((a * a - c * c) / a), B_((b * b - c * c) / b) {}
  std::string name() const override { return "ellipsoid"; }
  double surfaceArea() const override {  // Knud Thomsen's approximation (|error| < 1.1 %): only sets a spacing
    const double p = 1.6075, a = e_[0], b = e_[1], c = e_[2];
    return 4 * M_PI * std::pow((std::pow(a * b, p) + std::pow(a * c, p) + std::pow(b * c, p)) / 3, 1 / p);
  }
  double diagonal() const override { return 2 * norm(e_); }
  bool inside(const Vec3& p) const override {
    return p[0] * p[0] / (e_[0] * e_[0]) + p[1] * p[1] / (e_[1] * e_[1]) + p[2] * p[2] / (e_[2] * e_[2]) < 1;
  }
  double surfaceDistance(const Vec3& p) const override { return ellipsoidDistance(e_, p); }
  double innerAxisDistance(const Vec3& p) const override {
    return std::hypot(p[2], filledEllipseDistance(A_, B_, p[0], p[1]));
  }
  double wholeAxisDistance(const Vec3& p) const override { return innerAxisDistance(p); }
  Vec3 randomSurfacePoint(std::mt19937& rng) const override {
    // Uniform on the sphere mapped by diag(a, b, c), kept with probability
    // proportional to the area element |(bc x, ac y, ab z)| (max ab).
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> u(0, 1);
    const double a = e_[0], b = e_[1], c = e_[2];
    for (;;) {
      Vec3 v{g(rng), g(rng), g(rng)};
      const double l = norm(v);
      for (double& x : v) x /= l;
      const double element = norm(Vec3{b * c * v[0], a * c * v[1], a * b * v[2]});
      if (u(rng) * a * b <= element) return {a * v[0], b * v[1], c * v[2]};
    }
  }

 private:
  Vec3 e_;
  double A_, B_;
};

class Torus : public AnalyticShape {
 public:
  Torus(double R, double r) : R_(R), r_(r) {}
  std::string name() const override { return "torus"; }
  double surfaceArea() const override { return 4 * M_PI * M_PI * R_ * r_; }
  double diagonal() const override { return std::sqrt(8 * (R_ + r_) * (R_ + r_) + 4 * r_ * r_); }
  bool inside(const Vec3& p) const override { return tube(p) < r_; }
  double surfaceDistance(const Vec3& p) const override { return std::abs(tube(p) - r_); }
  double innerAxisDistance(const Vec3& p) const override { return tube(p); }
  double wholeAxisDistance(const Vec3& p) const override { return std::min(tube(p), std::hypot(p[0], p[1])); }
  Vec3 randomSurfacePoint(std::mt19937& rng) const override {
    std::uniform_real_distribution<double> angle(0, 2 * M_PI), u(0, 1);
    for (;;) {
      const double s = angle(rng), t = angle(rng);
      if (u(rng) * (R_ + r_) > R_ + r_ * std::cos(t)) continue;  // area element ∝ R + r cos t
      const double rho = R_ + r_ * std::cos(t);
      return {rho * std::cos(s), rho * std::sin(s), r_ * std::sin(t)};
    }
  }

 private:
  double tube(const Vec3& p) const { return std::hypot(std::hypot(p[0], p[1]) - R_, p[2]); }
  double R_, r_;
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}

}  // namespace

std::unique_ptr<AnalyticShape> makeSphere(double radius) { return std::make_unique<Sphere>(radius); }
std::unique_ptr<AnalyticShape> makeEllipsoid(double a, double b, double c) {
  return std::make_unique<Ellipsoid>(a, b, c);
}
std::unique_ptr<AnalyticShape> makeTorus(double R, double r) { return std::make_unique<Torus>(R, r); }

double ellipsoidDistance(const Vec3& e, const Vec3& p) {
  // By symmetry work in the first octant: the closest point keeps the signs.
  const double y0 = std::abs(p[0]), y1 = std::abs(p[1]), y2 = std::abs(p[2]);
  const double e0 = e[0], e1 = e[1], e2 = e[2];
  if (y2 > 0) {
    // x_i = e_i² y_i / (t + e_i²) with t the root of Σ (e_i y_i / (t + e_i²))² = 1
    // on (−e2², ∞), where the sum decreases from +∞.
    auto f = [&](double t) {
      const double a = e0 * y0 / (t + e0 * e0), b = e1 * y1 / (t + e1 * e1), c = e2 * y2 / (t + e2 * e2);
      return a * a + b * b + c * c - 1;
    };
    const double hi = -e2 * e2 + std::sqrt((e0 * y0) * (e0 * y0) + (e1 * y1) * (e1 * y1) + (e2 * y2) * (e2 * y2));
    const double t = bisect(f, -e2 * e2 + e2 * y2, hi);
    const double x0 = e0 * e0 * y0 / (t + e0 * e0), x1 = e1 * e1 * y1 / (t + e1 * e1),
                 x2 = e2 * e2 * y2 / (t + e2 * e2);
    return norm(Vec3{x0 - y0, x1 - y1, x2 - y2});
  }
  // On the plane z = 0: inside the focal region the closest points are the
  // pair (x0, x1, ±x2) with t = −e2² (the point is on the medial axis);
  // otherwise the closest point is on the section ellipse.
  if (e0 > e2 && e1 > e2) {
    const double x0 = e0 * e0 * y0 / (e0 * e0 - e2 * e2), x1 = e1 * e1 * y1 / (e1 * e1 - e2 * e2);
    const double s = (x0 / e0) * (x0 / e0) + (x1 / e1) * (x1 / e1);
    if (s < 1) return norm(Vec3{x0 - y0, x1 - y1, e2 * std::sqrt(1 - s)});
  }
  return ellipseCurveDistance(e0, e1, y0, y1);
}

double filledEllipseDistance(double A, double B, double x, double y) {
  if ((x / A) * (x / A) + (y / B) * (y / B) <= 1) return 0;
  return A >= B ? ellipseCurveDistance(A, B, std::abs(x), std::abs(y))
                : ellipseCurveDistance(B, A, std::abs(y), std::abs(x));
}

std::vector<Vec3> sampleSurface(const AnalyticShape& shape, std::size_t count, unsigned seed, double noise) {
  std::mt19937 rng(seed);
  // Greedy random sequential adsorption fills about 0.7 A / δ² discs; aim a
  // little below so `count` is reached before the candidates run out.
  const double delta = std::sqrt(0.62 * shape.surfaceArea() / static_cast<double>(count));
  auto key = [delta](const Vec3& p) {
    auto c = [delta](double x) { return static_cast<std::int64_t>(std::floor(x / delta)) & 0x1fffff; };
    return (c(p[0]) << 42) | (c(p[1]) << 21) | c(p[2]);
  };
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> grid;
  std::vector<Vec3> points;
  for (std::size_t tries = 0; tries < 20 * count && points.size() < count; ++tries) {
    const Vec3 p = shape.randomSurfacePoint(rng);
    bool clear = true;
    for (int dx = -1; dx <= 1 && clear; ++dx)
      for (int dy = -1; dy <= 1 && clear; ++dy)
        for (int dz = -1; dz <= 1 && clear; ++dz) {
          const auto it = grid.find(key({p[0] + dx * delta, p[1] + dy * delta, p[2] + dz * delta}));
          if (it == grid.end()) continue;
          for (std::uint32_t i : it->second) {
            const Vec3& q = points[i];
            if (norm(Vec3{p[0] - q[0], p[1] - q[1], p[2] - q[2]}) < delta) {
              clear = false;
              break;
            }
          }
        }
    if (!clear) continue;
    grid[key(p)].push_back(static_cast<std::uint32_t>(points.size()));
    points.push_back(p);
  }
  if (noise > 0) {
    std::uniform_real_distribution<double> u(-noise * shape.diagonal(), noise * shape.diagonal());
    for (Vec3& p : points)
      for (double& x : p) x += u(rng);
  }
  return points;
}

AnalyticMeasure measureAgainstShape(const MedialComplex& axis, const AnalyticShape& shape, bool wholeAxis,
                                    std::size_t boundaryPoints, double tolFraction) {
  AnalyticMeasure m;
  const double diag = shape.diagonal(), tol = tolFraction * diag;
  std::vector<std::uint8_t> used(axis.vertices.size(), 0);
  for (Index v : axis.polygonVertices) used[v] = 1;
  std::vector<double> medial, axisDist;
  std::vector<BallTree::Ball> balls;
  std::size_t inside = 0;
  for (std::size_t v = 0; v < axis.vertices.size(); ++v) {
    if (!used[v] || !(axis.radius[v] > 0)) continue;
    const Vec3& p = axis.vertices[v];
    medial.push_back(std::abs(shape.surfaceDistance(p) - axis.radius[v]) / diag);
    axisDist.push_back((wholeAxis ? shape.wholeAxisDistance(p) : shape.innerAxisDistance(p)) / diag);
    if (shape.inside(p)) {
      ++inside;
      balls.push_back({p, axis.radius[v]});
    }
  }
  m.vertices = medial.size();
  if (m.vertices == 0) return m;
  m.medialMedian = quantile(medial, 0.5);
  m.medialP90 = quantile(medial, 0.9);
  m.axisMedian = quantile(axisDist, 0.5);
  m.axisP90 = quantile(axisDist, 0.9);
  m.axisP99 = quantile(axisDist, 0.99);
  m.axisMax = *std::max_element(axisDist.begin(), axisDist.end());
  m.farShare = static_cast<double>(std::count_if(axisDist.begin(), axisDist.end(),
                                                 [&](double d) { return d > 2 * tolFraction; })) /
               static_cast<double>(axisDist.size());
  m.insideShare = static_cast<double>(inside) / static_cast<double>(m.vertices);
  const BallTree tree(std::move(balls));
  std::mt19937 rng(12345);
  std::size_t covered = 0;
  for (std::size_t i = 0; i < boundaryPoints; ++i)
    if (tree.minGap(shape.randomSurfacePoint(rng), tol) <= tol) ++covered;
  m.coverage = static_cast<double>(covered) / static_cast<double>(boundaryPoints);
  return m;
}

}  // namespace cadmedial::testing
