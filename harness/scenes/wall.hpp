// An in-plane masonry wall as rigid blocks joined by zero-thickness
// interfaces: the units, enlarged by half a joint on each side as
// in discrete-element practice, are rigid bodies with three degrees of
// freedom (ux, uy, rotation about their centroid); every bed and head joint is
// a row of contact points that vuinteraction_ sees with nDir = 2 (normal and
// one tangent). A rigid base below and a rigid top beam above close the
// wall. Small displacements and rotations: the kinematics are linear and
// equilibrium is written in the undeformed configuration (no P-delta).
//
// Units: N, mm, s, tonnes (1 t = 1000 kg: N = t·mm/s²), MPa.
#pragma once

#include <string>
#include <vector>

namespace mortar::harness {

enum class Bond { running, stack };
enum class PointRule { trapezoid, midpoint };
enum class BeamRotation { fixed, free };
// What an interface is, each with its own joint law (scene file
// [interfaces]): a bed joint (horizontal, the base and the top beam's
// included), a head joint, or the potential crack through the middle of a
// unit (a unit split into two rigid halves).
enum class InterfaceRole { bed = 0, head = 1, unit_crack = 2 };
constexpr int kInterfaceRoles = 3;
const char* role_name(InterfaceRole r);

struct WallGeometry {
  double unit_length = 0, unit_height = 0, unit_depth = 0;  // the unit itself [mm]
  double joint = 0;                                          // mortar joint thickness [mm]
  double density = 0;                                        // of the enlarged units [t/mm³]
  int courses = 0;
  double units_per_course = 0;  // whole or half units (4.5: four full units and a half)
  Bond bond = Bond::running;
  // A course clamped in the base or the top beam (the TU Eindhoven walls):
  // its units become part of that rigid body and its joints disappear.
  bool tie_bottom_course = false, tie_top_course = false;
  double beam_mass = 0;    // top beam [t]
  double beam_height = 0;  // top beam [mm], for its inertia and pictures
  BeamRotation beam_rotation = BeamRotation::fixed;
  // The beam's uy: free under its weight and the precompression, or held at
  // its height from the end of the hold on (the TU Eindhoven set-up).
  bool beam_held = false;
  // Each unit as two rigid halves joined by a unit-crack interface through
  // its middle (Lourenço's potential cracks; scene file [interfaces] unit_crack).
  bool split_units = false;
  int points_per_face = 2;  // contact points on each face between two bodies
  PointRule rule = PointRule::trapezoid;
};

// A rigid body. Its degrees of freedom are the displacements of its centroid
// and its rotation (counter-clockwise positive).
struct Body {
  double cx = 0, cy = 0;       // centroid [mm]
  double mass = 0;             // [t]
  double inertia = 0;          // about the centroid [t·mm²]
  std::vector<double> corners; // outline x0,y0,x1,y1,... (pictures)
  int course = -1;             // -1: base, courses: top beam
};

// One contact point of a joint between body a (below / left) and body b
// (above / right). The normal points from a to b; the tangent is the normal
// turned clockwise (a bed joint's tangent is +x, a head joint's -y).
struct ContactPoint {
  int a = 0, b = 0;
  double x = 0, y = 0;    // position [mm]
  double nx = 0, ny = 0;  // unit normal
  double area = 0;        // tributary area [mm²]
  bool bed = true;        // bed (horizontal) or head (vertical) joint
  int joint = 0;          // which joint face (pictures: one segment each)
  InterfaceRole role = InterfaceRole::bed;
  double tx() const { return ny; }
  double ty() const { return -nx; }
};

struct WallModel {
  // Body 0 is the base (fixed), the last body the top beam; the blocks lie
  // between, course by course from the bottom, left to right.
  std::vector<Body> bodies;
  std::vector<ContactPoint> points;
  int joint_faces = 0;
  double length = 0;  // of the wall [mm]
  double height = 0;  // from the base to the underside of the top beam [mm]
  int base() const { return 0; }
  int beam() const { return static_cast<int>(bodies.size()) - 1; }
  int blocks() const { return static_cast<int>(bodies.size()) - 2; }
  // Indices of the base-joint points (those that touch body 0).
  std::vector<int> base_points() const;
};

// The length of unit material lumped into an interface of role r, half a
// unit on each side along its normal (docs: harness/README.md, "scene"):
// a bed joint unit_height, a head joint unit_length (half with split
// units), a unit crack unit_length / 2.
double lumped_unit_length(const WallGeometry& g, InterfaceRole r);

// Builds the bodies and contact points, the points grouped by role (bed
// joints, head joints, unit cracks, in this order). The geometry must have been checked
// (input/scene_file.cpp); std::invalid_argument otherwise.
WallModel build_wall(const WallGeometry& g);

}  // namespace mortar::harness
