#include "scenes/wall.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mortar::harness {

namespace {

struct Piece {
  double x0, x1;
  int body;
  bool crack_after = false;  // the boundary at x1 is a unit crack (not a head joint)
};

std::vector<double> rectangle(double x0, double y0, double x1, double y1) {
  return {x0, y0, x1, y0, x1, y1, x0, y1};
}

// Adds a mass m with its centroid (cx, cy) and its own rotary inertia to a
// body (parallel-axis theorem).
void add_part(Body& b, double m, double cx, double cy, double inertia) {
  const double total = b.mass + m;
  if (total <= 0) return;
  const double ncx = (b.mass * b.cx + m * cx) / total, ncy = (b.mass * b.cy + m * cy) / total;
  const double ib = b.inertia + b.mass * ((b.cx - ncx) * (b.cx - ncx) + (b.cy - ncy) * (b.cy - ncy));
  const double ip = inertia + m * ((cx - ncx) * (cx - ncx) + (cy - ncy) * (cy - ncy));
  b.mass = total, b.cx = ncx, b.cy = ncy, b.inertia = ib + ip;
}

// Adds a rectangle of mass to a body, so that a tied course and the beam
// (or the base) become one rigid body.
void add_mass(Body& b, double x0, double y0, double x1, double y1, double density, double depth) {
  const double w = x1 - x0, h = y1 - y0, m = w * h * depth * density;
  add_part(b, m, 0.5 * (x0 + x1), 0.5 * (y0 + y1), m * (w * w + h * h) / 12);
}

// The x-intervals of course c: running bond starts every other course with
// a half unit, so the vertical joints of neighbouring courses are half a
// unit apart; a course ends where the wall ends (a half unit when the
// length is an odd number of half units).
std::vector<std::pair<double, double>> course_pieces(const WallGeometry& g, int c, double length) {
  const double bl = g.unit_length + g.joint, eps = 1e-9 * bl;
  std::vector<std::pair<double, double>> out;
  double x = 0;
  if (g.bond == Bond::running && c % 2 == 1) {
    out.push_back({0, std::min(0.5 * bl, length)});
    x = out.back().second;
  }
  while (x < length - eps) {
    const double end = std::min(x + bl, length);
    out.push_back({x, end});
    x = end;
  }
  return out;
}

// n points on [s0, s1] of a face of the given depth: positions and
// tributary lengths times depth.
void face_points(const WallGeometry& g, double s0, double s1, std::vector<double>& s, std::vector<double>& area) {
  const int n = g.points_per_face;
  s.clear(), area.clear();
  if (g.rule == PointRule::midpoint || n == 1) {
    const double h = (s1 - s0) / n;
    for (int i = 0; i < n; ++i) s.push_back(s0 + (i + 0.5) * h), area.push_back(h * g.unit_depth);
    return;
  }
  // Trapezoid: points at both ends (a rocking joint turns about its very
  // edge), the end points carry half a spacing.
  const double h = (s1 - s0) / (n - 1);
  for (int i = 0; i < n; ++i) {
    s.push_back(s0 + i * h);
    area.push_back((i == 0 || i == n - 1 ? 0.5 : 1.0) * h * g.unit_depth);
  }
}

class Builder {
 public:
  explicit Builder(const WallGeometry& g) : g_(g) {
    bl_ = g.unit_length + g.joint;
    bh_ = g.unit_height + g.joint;
    m_.length = g.units_per_course * bl_;
    m_.height = g.courses * bh_;
  }

  WallModel build() {
    make_bodies();
    for (int k = 0; k <= g_.courses; ++k) bed_joint(k);
    for (int c = 0; c < g_.courses; ++c) vertical_interfaces(c, InterfaceRole::head);
    for (int c = 0; c < g_.courses; ++c) vertical_interfaces(c, InterfaceRole::unit_crack);
    return std::move(m_);
  }

 private:
  bool tied_to_base(int c) const { return g_.tie_bottom_course && c == 0; }
  bool tied_to_beam(int c) const { return g_.tie_top_course && c == g_.courses - 1; }

  void make_bodies() {
    const double L = m_.length, H = m_.height;
    Body base;
    base.course = -1;
    base.cx = 0.5 * L, base.cy = -0.5 * bh_;
    base.corners = rectangle(0, -bh_, L, tied_to_base(0) ? bh_ : 0);
    m_.bodies.push_back(base);
    layers_.assign(g_.courses, {});
    std::vector<std::pair<int, std::pair<double, double>>> beam_parts;
    for (int c = 0; c < g_.courses; ++c) {
      for (const auto& [x0, x1] : course_pieces(g_, c, L)) {
        int owner;
        if (tied_to_base(c)) {
          owner = 0;
        } else if (tied_to_beam(c)) {
          owner = -2;  // the beam, numbered once all blocks exist
          beam_parts.push_back({c, {x0, x1}});
        } else if (g_.split_units) {
          const double xm = 0.5 * (x0 + x1);
          layers_[c].push_back({x0, xm, add_block(c, x0, xm), true});
          layers_[c].push_back({xm, x1, add_block(c, xm, x1)});
          continue;
        } else {
          owner = add_block(c, x0, x1);
        }
        layers_[c].push_back({x0, x1, owner});
      }
    }
    Body beam;
    beam.course = g_.courses;
    if (g_.beam_height > 0)
      add_mass(beam, 0, H, L, H + g_.beam_height, g_.beam_mass / (L * g_.beam_height * g_.unit_depth), g_.unit_depth);
    else  // a beam of no height: its mass along the top of the wall
      add_part(beam, g_.beam_mass, 0.5 * L, H, g_.beam_mass * L * L / 12);
    for (const auto& part : beam_parts)
      add_mass(beam, part.second.first, part.first * bh_, part.second.second, (part.first + 1) * bh_, g_.density,
               g_.unit_depth);
    beam.corners = rectangle(0, g_.tie_top_course ? H - bh_ : H, L, H + g_.beam_height);
    m_.bodies.push_back(beam);
    for (auto& layer : layers_)
      for (Piece& p : layer)
        if (p.body == -2) p.body = m_.beam();
  }

  int add_block(int c, double x0, double x1) {
    const double y0 = c * bh_, y1 = y0 + bh_;
    Body b;
    b.course = c;
    add_mass(b, x0, y0, x1, y1, g_.density, g_.unit_depth);
    b.corners = rectangle(x0, y0, x1, y1);
    m_.bodies.push_back(b);
    return static_cast<int>(m_.bodies.size()) - 1;
  }

  std::vector<Piece> layer(int c) const {
    if (c < 0) return {{0, m_.length, 0}};
    if (c >= g_.courses) return {{0, m_.length, m_.beam()}};
    return layers_[c];
  }

  // The bed joint at the bottom of course k (k = courses: under the beam).
  void bed_joint(int k) {
    const double eps = 1e-9 * bl_;
    std::vector<double> s, area;
    for (const Piece& lo : layer(k - 1))
      for (const Piece& up : layer(k)) {
        const double x0 = std::max(lo.x0, up.x0), x1 = std::min(lo.x1, up.x1);
        if (x1 - x0 <= eps || lo.body == up.body) continue;
        face_points(g_, x0, x1, s, area);
        for (size_t i = 0; i < s.size(); ++i)
          m_.points.push_back({lo.body, up.body, s[i], k * bh_, 0.0, 1.0, area[i], true, m_.joint_faces, InterfaceRole::bed});
        ++m_.joint_faces;
      }
  }

  // The head joints (or the unit cracks) of course c.
  void vertical_interfaces(int c, InterfaceRole role) {
    if (tied_to_base(c) || tied_to_beam(c)) return;
    std::vector<double> s, area;
    const auto& pieces = layers_[c];
    for (size_t j = 0; j + 1 < pieces.size(); ++j) {
      if (pieces[j].crack_after != (role == InterfaceRole::unit_crack)) continue;
      face_points(g_, c * bh_, (c + 1) * bh_, s, area);
      for (size_t i = 0; i < s.size(); ++i)
        m_.points.push_back(
            {pieces[j].body, pieces[j + 1].body, pieces[j].x1, s[i], 1.0, 0.0, area[i], false, m_.joint_faces, role});
      ++m_.joint_faces;
    }
  }

  const WallGeometry& g_;
  double bl_ = 0, bh_ = 0;
  WallModel m_;
  std::vector<std::vector<Piece>> layers_;
};

}  // namespace

double lumped_unit_length(const WallGeometry& g, InterfaceRole r) {
  switch (r) {
    case InterfaceRole::bed: return g.unit_height;
    case InterfaceRole::head: return g.split_units ? 0.5 * g.unit_length : g.unit_length;
    case InterfaceRole::unit_crack: return 0.5 * g.unit_length;
  }
  return 0;
}

const char* role_name(InterfaceRole r) {
  switch (r) {
    case InterfaceRole::bed: return "bed joint";
    case InterfaceRole::head: return "head joint";
    case InterfaceRole::unit_crack: return "unit crack";
  }
  return "?";
}

std::vector<int> WallModel::base_points() const {
  std::vector<int> out;
  for (size_t i = 0; i < points.size(); ++i)
    if (points[i].a == base()) out.push_back(static_cast<int>(i));
  return out;
}

WallModel build_wall(const WallGeometry& g) {
  if (g.courses < 1 || g.units_per_course <= 0 || g.unit_length <= 0 || g.unit_height <= 0 || g.unit_depth <= 0 ||
      g.points_per_face < 1)
    throw std::invalid_argument("build_wall: unchecked geometry");
  WallModel m = Builder(g).build();
  if (m.bodies.back().mass <= 0) throw std::invalid_argument("build_wall: the top beam has no mass");
  return m;
}

}  // namespace mortar::harness
