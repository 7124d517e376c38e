#include "output/wall_deck.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <ostream>
#include <set>
#include <string>

#include "input/input_error.hpp"
#include "output/inp_deck.hpp"
#include "output/inp_mesh.hpp"

namespace mortar::harness {

namespace {

// The joint roles, each its own interaction and pair of surfaces: A the
// lower/left bodies' faces, B the upper/right ones'.
enum Role { kBed, kHead, kBase, kTop, kUnitCrack, kRoles };
const char* const kRoleNames[kRoles] = {"BED", "HEAD", "BASE", "TOP", "UNIT-CRACK"};

// The scene's interface role whose law a deck role gets.
InterfaceRole law_of(int r) {
  return r == kHead ? InterfaceRole::head : r == kUnitCrack ? InterfaceRole::unit_crack : InterfaceRole::bed;
}

Role role_of(const WallModel& m, const ContactPoint& p) {
  if (p.role == InterfaceRole::unit_crack) return kUnitCrack;
  if (!p.bed) return kHead;
  if (p.a == m.base()) return kBase;
  if (p.b == m.beam()) return kTop;
  return kBed;
}

std::string body_name(const WallModel& m, int b) {
  if (b == m.base()) return "BASE";
  if (b == m.beam()) return "BEAM";
  return "UNIT-" + std::to_string(b);
}

std::string num(double x) { return exact_decimal(x); }

// *AMPLITUDE, DEFINITION=SMOOTH STEP through (time, value) corners: between
// two corners a step with zero velocity and acceleration at both ends (the
// scene's half cosines have the same corners and zero end velocities). On
// total time, so that a held beam's second step keeps the same histories.
void write_amplitude(std::ostream& out, const std::string& name, const std::vector<std::pair<double, double>>& pts) {
  out << "*AMPLITUDE, NAME=" << name << ", TIME=TOTAL TIME, DEFINITION=SMOOTH STEP\n";
  for (size_t i = 0; i < pts.size(); ++i)
    out << num(pts[i].first) << ", " << num(pts[i].second) << (i + 1 == pts.size() || i % 4 == 3 ? "\n" : ", ");
}

class WallDeck {
 public:
  WallDeck(const SceneSpec& s, const WallModel& m)
      : s_(s), m_(m), arm_(action_arm(s, m)) {}

  void write(std::ostream& out, double dt) {
    mesh_bodies();
    plan_damping();
    out << "*HEADING\n"
        << "Wall of " << m_.blocks() << " rigid units from the scene " << s_.file << " (masonry-joint inp --scene)\n"
        << "** Units N, mm, s, t (tonne), MPa. In-plane wall (x along the wall, y up) extruded over the unit\n"
        << "** depth in z; every body is a rigid body, its reference node at the scene's centroid.\n";
    mesh_.write_nodes(out);
    mesh_.write_elements(out, "C3D8R");
    write_sets(out);
    write_materials(out);
    write_damping(out);
    write_interactions(out);
    write_step(out, dt);
  }

 private:
  void mesh_bodies() {
    const WallGeometry& g = s_.wall;
    const int per = std::max(1, g.points_per_face - 1);
    const double hx = (g.unit_length + g.joint) / per, hy = (g.unit_height + g.joint) / per;
    for (int b = 0; b < static_cast<int>(m_.bodies.size()); ++b) {
      const std::vector<double>& c = m_.bodies[static_cast<size_t>(b)].corners;
      double x0 = c[0], y0 = c[1], x1 = c[4], y1 = c[5];
      if (y1 - y0 <= 0) y1 = y0 + g.unit_height + g.joint;  // a beam of no height: one course high
      const int nx = std::max(1, static_cast<int>(std::lround((x1 - x0) / hx)));
      const int ny = std::max(1, static_cast<int>(std::lround((y1 - y0) / hy)));
      boxes_.push_back(mesh_.add_box(body_name(m_, b), {x0, y0, 0.0}, {x1, y1, g.unit_depth}, {nx, ny, 1}));
      volume_.push_back((x1 - x0) * (y1 - y0) * g.unit_depth);
      extent_.push_back({x0, y0, x1, y1});
    }
    for (const Body& b : m_.bodies) refs_.push_back(mesh_.add_node(b.cx, b.cy, 0.5 * g.unit_depth));
  }

  void write_sets(std::ostream& out) {
    std::vector<int> moving, free_refs;
    for (int b = 1; b < static_cast<int>(m_.bodies.size()); ++b) {
      const MeshBox& box = mesh_.box(boxes_[static_cast<size_t>(b)]);
      for (int e = 0; e < box.n[0] * box.n[1] * box.n[2]; ++e) moving.push_back(box.first_element + e);
      free_refs.push_back(refs_[static_cast<size_t>(b)]);
    }
    write_set(out, "*ELSET, ELSET=MOVING", moving);
    write_set(out, "*NSET, NSET=FREE-REFS", free_refs);
    write_set(out, "*NSET, NSET=BASE-REF", {refs_.front()});
    write_set(out, "*NSET, NSET=BEAM-REF", {refs_.back()});
    for (int b = 0; b < static_cast<int>(m_.bodies.size()); ++b)
      out << "*RIGID BODY, REF NODE=" << refs_[static_cast<size_t>(b)] << ", ELSET=" << body_name(m_, b) << "\n";
  }

  void write_materials(std::ostream& out) const {
    // Rigid bodies take their mass and rotary inertia from their elements:
    // the units' density is the scene's (enlarged units), the beam's spreads
    // the scene's beam mass (tied course included) over its box.
    const double beam_density = m_.bodies.back().mass / volume_.back();
    for (int b = 0; b < static_cast<int>(m_.bodies.size()); ++b)
      out << "*SOLID SECTION, ELSET=" << body_name(m_, b) << ", MATERIAL=" << (b == m_.beam() ? "BEAM" : "UNIT")
          << "\n";
    for (const auto& [name, density] : {std::pair<const char*, double>{"UNIT", s_.wall.density}, {"BEAM", beam_density}})
      out << "*MATERIAL, NAME=" << name << "\n*DENSITY\n" << num(density) << ",\n*ELASTIC\n30000., 0.2\n";
  }

  // The scene's C = alpha·M (masses and inertias times the mass scaling) as
  // DASHPOTA elements to fixed ground nodes: DASHPOT1/DASHPOT2 and torsional
  // dashpots are Abaqus/Standard only. Each dashpot lies along x or y, its
  // ground node far along that line (kGroundDistance wall lengths). At the
  // reference node: the translational part; at two corner nodes of the box
  // on either side of the reference node (an x pair above and below it, a y
  // pair left and right of it, coefficients in inverse ratio of the offsets
  // so that they add no coupling): the rotational part, which adds
  // translational damping K/cap to each pair's direction, taken off the
  // reference node's dashpot (cap = sum of the pairs' offset products).
  struct Dashpot {
    std::string set;
    int node = 0, ground = 0;
    double c = 0;
  };
  static constexpr double kGroundDistance = 1000.0;

  void plan_damping() {
    const double alpha = s_.solver.mass_damping, f = s_.solver.mass_scaling;
    if (alpha <= 0) return;
    const double far = kGroundDistance * std::max(m_.length, 1.0);
    for (int b = 1; b < static_cast<int>(m_.bodies.size()); ++b) {
      const Body& body = m_.bodies[static_cast<size_t>(b)];
      const bool beam = b == m_.beam();
      const bool free_x = !beam || s_.loading.force_control;
      const bool free_r = !(beam && s_.wall.beam_rotation == BeamRotation::fixed);
      const MeshBox& box = mesh_.box(boxes_[static_cast<size_t>(b)]);
      const std::array<double, 4>& e = extent_[static_cast<size_t>(b)];  // x0, y0, x1, y1
      const auto corner = [&](int i, int j) { return box.first_node + i + (box.n[0] + 1) * j; };
      const double above = e[3] - body.cy, below = body.cy - e[1], right = e[2] - body.cx, left = body.cx - e[0];
      const double cap_x = free_x ? above * below : 0, cap_y = right * left, cap = cap_x + cap_y;
      const double M = alpha * f * body.mass, K = free_r ? alpha * f * body.inertia : 0;
      if (K > 0 && !(cap > 0 && K <= M * cap))
        throw InputError(s_.file + ": [solver] mass_damping = " + num(alpha) + ": the rotational damping of " +
                         body_name(m_, b) + ", alpha·I = " + num(K) +
                         " t·mm²/s, exceeds alpha·m·(sum of the corner offset products) = " + num(M * cap) +
                         ", the most that dashpots at its box corners give (inp --scene); set mass_damping = 0 for "
                         "a deck");
      const double pair_t = K > 0 ? K / cap : 0;  // translational damping added by each pair
      const std::string name = "DAMP-" + body_name(m_, b) + "-";
      const auto add = [&](const std::string& tag, int node, double x, double y, double z, bool along_x, double c) {
        if (c <= 0) return;
        const int ground = mesh_.add_node(along_x ? x + far : x, along_x ? y : y + far, z);
        dashpots_.push_back({name + tag, node, ground, c});
      };
      const int ref = refs_[static_cast<size_t>(b)];
      const double zr = 0.5 * s_.wall.unit_depth;  // the reference nodes' z; the corners' is 0
      if (free_x) add("X", ref, body.cx, body.cy, zr, true, M - (cap_x > 0 ? pair_t : 0));
      add("Y", ref, body.cx, body.cy, zr, false, M - (cap_y > 0 ? pair_t : 0));
      if (K > 0 && cap_x > 0) {  // x pair: bottom-left and top-left corners, c·offset equal
        const double r = K * cap_x / cap, c_top = r / (above * (above + below)), c_bottom = c_top * above / below;
        add("XB", corner(0, 0), e[0], e[1], 0.0, true, c_bottom);
        add("XT", corner(0, box.n[1]), e[0], e[3], 0.0, true, c_top);
      }
      if (K > 0 && cap_y > 0) {  // y pair: bottom-left and bottom-right corners
        const double r = K * cap_y / cap, c_right = r / (right * (right + left)), c_left = c_right * right / left;
        add("YL", corner(0, 0), e[0], e[1], 0.0, false, c_left);
        add("YR", corner(box.n[0], 0), e[2], e[1], 0.0, false, c_right);
      }
    }
  }

  void write_damping(std::ostream& out) const {
    if (dashpots_.empty()) return;
    int element = mesh_.elements();
    std::vector<int> ground;
    for (const Dashpot& d : dashpots_) {
      out << "*ELEMENT, TYPE=DASHPOTA, ELSET=" << d.set << "\n" << ++element << ", " << d.node << ", " << d.ground
          << "\n*DASHPOT, ELSET=" << d.set << "\n\n" << num(d.c) << "\n";
      ground.push_back(d.ground);
    }
    write_set(out, "*NSET, NSET=DAMP-GROUND", ground);
  }

  void write_interactions(std::ostream& out) {
    std::set<std::pair<int, int>> seen[kRoles][2];  // (body, side) already on a surface
    std::vector<ElementFace> faces[kRoles][2];
    for (const ContactPoint& p : m_.points) {
      const Role r = role_of(m_, p);
      const int body[2] = {p.a, p.b};
      const BoxSide sides[2] = {p.bed ? BoxSide::ymax : BoxSide::xmax, p.bed ? BoxSide::ymin : BoxSide::xmin};
      for (int k = 0; k < 2; ++k)
        if (seen[r][k].insert({body[k], static_cast<int>(sides[k])}).second)
          for (const ElementFace& f : mesh_.side(boxes_[static_cast<size_t>(body[k])], sides[k]))
            faces[r][k].push_back(f);
    }
    InpOptions o;
    const bool controls = s_.scheme != Scheme::modified_euler || s_.stol != 0;
    for (int r = 0; r < kRoles; ++r) {
      if (faces[r][0].empty()) continue;
      roles_.push_back(r);
      const auto law = static_cast<size_t>(law_of(r));
      o.props = deck_props(s_.interface_law[law], controls, s_.scheme != Scheme::modified_euler, s_.scheme, s_.stol,
                           s_.interface[law].cap);
      o.depvar = deck_depvar(o.props, false);
      write_element_surface(out, std::string(kRoleNames[r]) + "-A", faces[r][0]);
      write_element_surface(out, std::string(kRoleNames[r]) + "-B", faces[r][1]);
      o.name = std::string("MORTAR-") + kRoleNames[r];
      out << "** " << kRoleNames[r] << ": the law of " << s_.interface[law].file
          << (s_.units.young > 0 ? ", kn and ks in series with the units ([units])" : "") << "\n";
      write_surface_interaction(out, o);
    }
  }

  // One step, or with a held beam two: the second, from the end of the hold
  // on, holds the beam's U2 where the first left it (a zero velocity: FIXED
  // is Abaqus/Standard only). Loads, supports, amplitudes (on total time)
  // and output requests carry over into it.
  void write_step(std::ostream& out, double dt) const {
    const std::vector<double> ends = s_.stage_ends();
    const double T = ends.back();
    const bool force = s_.loading.force_control, held = s_.wall.beam_held;
    write_amplitude(out, "SELF-WEIGHT", {{0, 0}, {ends[0], 1}});
    write_amplitude(out, "PRECOMPRESSION", {{0, 0}, {ends[0], 0}, {ends[1], 1}});
    std::vector<std::pair<double, double>> legs = {{0, 0}, {ends[2], 0}};
    for (size_t k = 0; k < s_.loading.corners().size(); ++k) legs.push_back({ends[3 + k], s_.loading.corners()[k]});
    write_amplitude(out, force ? "TOP-FORCE" : "TOP-DISPLACEMENT", legs);
    out << "*STEP, NAME=" << (held ? "LOAD" : "WALL") << "\n*DYNAMIC, EXPLICIT, DIRECT USER CONTROL\n" << num(dt)
        << ", " << num(held ? ends[2] : T) << "\n";
    if (s_.solver.mass_scaling != 1) out << "*FIXED MASS SCALING, FACTOR=" << num(s_.solver.mass_scaling) << "\n";
    out << "*CONTACT\n*CONTACT INCLUSIONS\n";
    for (int r : roles_) out << kRoleNames[r] << "-A, " << kRoleNames[r] << "-B\n";
    out << "*CONTACT PROPERTY ASSIGNMENT\n";
    for (int r : roles_) out << kRoleNames[r] << "-A, " << kRoleNames[r] << "-B, MORTAR-" << kRoleNames[r] << "\n";
    // Supports: the base fixed; every body in the plane; the beam's rotation
    // as the scene says; its ux through the displacement history, or free
    // under the force (and its moment about the reference node, arm above).
    out << "*BOUNDARY\nBASE-REF, ENCASTRE\nFREE-REFS, 3, 5\n";
    if (s_.wall.beam_rotation == BeamRotation::fixed) out << "BEAM-REF, 6, 6\n";
    if (!dashpots_.empty()) out << "DAMP-GROUND, 1, 3\n";
    if (force) {
      out << "*CLOAD, AMPLITUDE=TOP-FORCE\nBEAM-REF, 1, 1.\n";
      if (arm_ != 0 && s_.wall.beam_rotation == BeamRotation::free) out << "BEAM-REF, 6, " << num(-arm_) << "\n";
    } else {
      out << "*BOUNDARY, AMPLITUDE=TOP-DISPLACEMENT\nBEAM-REF, 1, 1, 1.\n";
    }
    out << "*DLOAD, AMPLITUDE=SELF-WEIGHT\nMOVING, GRAV, " << num(s_.loading.gravity) << ", 0., -1., 0.\n"
        << "*CLOAD, AMPLITUDE=PRECOMPRESSION\nBEAM-REF, 2, "
        << num(-s_.loading.precompression * m_.length * s_.wall.unit_depth) << "\n";
    out << "*OUTPUT, FIELD, NUMBER INTERVAL=100\n*NODE OUTPUT\nU, RF\n*CONTACT OUTPUT\nCSTRESS\n"
        << "*OUTPUT, HISTORY, TIME INTERVAL=" << num(T / 2000) << "\n"
        << "*NODE OUTPUT, NSET=BEAM-REF\nU1, U2, UR3, RF1, RF2\n*NODE OUTPUT, NSET=BASE-REF\nRF1, RF2, RM3\n"
        << "*ENERGY OUTPUT\nALLSE, ALLPD, ALLKE, ALLWK, ALLVD, ETOTAL\n*END STEP\n";
    if (held)
      out << "*STEP, NAME=HELD\n*DYNAMIC, EXPLICIT, DIRECT USER CONTROL\n" << num(dt) << ", " << num(T - ends[2])
          << "\n*BOUNDARY, TYPE=VELOCITY\nBEAM-REF, 2, 2, 0.\n*END STEP\n";
  }

  const SceneSpec& s_;
  const WallModel& m_;
  const double arm_;  // the action's height above the beam's centroid [mm]
  InpMesh mesh_;
  std::vector<int> boxes_, refs_, roles_;
  std::vector<double> volume_;
  std::vector<std::array<double, 4>> extent_;
  std::vector<Dashpot> dashpots_;
};

}  // namespace

void write_wall_deck(std::ostream& out, const SceneSpec& scene, const WallModel& model, double time_increment) {
  // A displacement at a height on a beam free to turn (the scene moves the
  // point at that height, the beam's rotation follows the equilibrium):
  // refused, not approximated. At the centroid, or with the rotation fixed,
  // the reference node's U1 is that point's.
  if (!scene.loading.force_control && scene.wall.beam_rotation == BeamRotation::free && action_arm(scene, model) != 0)
    throw InputError(scene.file + ": [loading] action_height = " + exact_decimal(scene.loading.action_height) +
                     " with a displacement and [top_beam] rotation = \"free\": inp --scene writes a displacement "
                     "at a height only at the beam's centroid (" +
                     exact_decimal(model.bodies[static_cast<size_t>(model.beam())].cy) +
                     " mm) or with the rotation fixed; run the scene, or use control = \"force\" for a deck");
  WallDeck(scene, model).write(out, time_increment);
}

}  // namespace mortar::harness
