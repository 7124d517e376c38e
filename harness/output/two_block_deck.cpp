#include "output/two_block_deck.hpp"

#include <ostream>
#include <string>

#include "output/inp_deck.hpp"
#include "output/inp_mesh.hpp"

namespace mortar::harness {

namespace {

constexpr int kLowerDivisions = 4;       // the lower block's top face: 4 × 4 elements, 25 contact nodes
constexpr double kBlockModulus = 1e7;    // [MPa]: h/E = 5e-6 mm/MPa against 1/kn = 1.3e-3 (M15)
constexpr double kBlockDensity = 1.8e-9; // [t/mm³], clay brick
const char* const kPairs[2] = {"SHEAR", "TENSION"};

std::string num(double x) { return exact_decimal(x); }

}  // namespace

void write_two_block_deck(std::ostream& out, const std::vector<double>& props, DeckSolver solver,
                          const TwoBlockLoading& l) {
  const bool standard = solver == DeckSolver::standard_contact_pair;
  const double a = l.side, h = l.height;
  InpMesh mesh;
  int lower[2], upper[2], ref[2];
  for (int p = 0; p < 2; ++p) {
    const double x0 = 2 * a * p;  // the pairs side by side, a block's width apart
    lower[p] = mesh.add_box(std::string(kPairs[p]) + "-LOWER", {x0, -h, 0}, {x0 + a, 0, a},
                            {kLowerDivisions, 1, kLowerDivisions});
    upper[p] = mesh.add_box(std::string(kPairs[p]) + "-UPPER", {x0, 0, 0}, {x0 + a, h, a}, {1, 1, 1});
  }
  for (int p = 0; p < 2; ++p) ref[p] = mesh.add_node(2 * a * p + 0.5 * a, 0.5 * h, 0.5 * a);

  out << "*HEADING\nTwo pairs of blocks on one mortar joint each: SHEAR pressed and sheared, TENSION pulled apart ("
      << (standard ? "Abaqus/Standard, UINTER" : "Abaqus/Explicit, VUINTERACTION") << ")\n"
      << "** Written by masonry-joint inp --two-blocks " << (standard ? "standard" : "explicit")
      << ". Units N, mm, s, t (tonne), MPa; y up.\n"
      << "** The joint is the plane y = 0 between a stiff elastic lower block (fixed at y = -" << num(h)
      << ") and a rigid upper block\n** loaded at its reference node: RF1 of SHEAR-REF = tau * "
      << num(a * a) << " mm2, RF2 of TENSION-REF = sigma_n * " << num(a * a) << " mm2.\n";
  mesh.write_nodes(out);
  const char* deformable = standard ? "C3D8" : "C3D8R";
  mesh.write_elements(out, deformable, {lower[0], lower[1]});
  mesh.write_elements(out, "C3D8R", {upper[0], upper[1]});
  for (int p = 0; p < 2; ++p) {
    const std::string pair = kPairs[p];
    write_set(out, "*NSET, NSET=" + pair + "-REF", {ref[p]});
    out << "*RIGID BODY, REF NODE=" << ref[p] << ", ELSET=" << pair << "-UPPER\n";
    write_set(out, "*NSET, NSET=" + pair + "-BASE", mesh.bottom_nodes(lower[p]));
    out << "*SOLID SECTION, ELSET=" << pair << "-LOWER, MATERIAL=BRICK\n"
        << "*SOLID SECTION, ELSET=" << pair << "-UPPER, MATERIAL=BRICK\n";
    write_element_surface(out, pair + "-LOWER-TOP", mesh.side(lower[p], BoxSide::ymax));
    write_element_surface(out, pair + "-UPPER-BOTTOM", mesh.side(upper[p], BoxSide::ymin));
  }
  out << "*MATERIAL, NAME=BRICK\n*DENSITY\n" << num(kBlockDensity) << ",\n*ELASTIC\n" << num(kBlockModulus)
      << ", 0.2\n";
  InpOptions o;
  o.name = "MORTAR";
  o.props = props;
  o.standard = standard;
  o.depvar = deck_depvar(props, standard);
  write_surface_interaction(out, o);

  if (standard) {
    // Model data in Abaqus/Standard (history data only in Abaqus/Explicit).
    out << "*CONTACT PAIR, INTERACTION=MORTAR\n";
    for (const char* p : kPairs) out << p << "-LOWER-TOP, " << p << "-UPPER-BOTTOM\n";
  }
  const double force = l.pressure * a * a;
  if (!standard) {
    const double t1 = l.explicit_time[0], t2 = t1 + l.explicit_time[1];
    out << "*AMPLITUDE, NAME=PRESS, TIME=TOTAL TIME, DEFINITION=SMOOTH STEP\n0., 0., " << num(t1) << ", 1.\n"
        << "*AMPLITUDE, NAME=SLIDE, TIME=TOTAL TIME, DEFINITION=SMOOTH STEP\n0., 0., " << num(t1) << ", 0., "
        << num(t2) << ", 1.\n";
  }
  for (int step = 0; step < 2; ++step) {
    out << "*STEP, NAME=" << (step == 0 ? "PRESS" : "SHEAR-AND-PULL");
    if (standard) {
      const double dt = 1.0 / double(l.increments[step]);
      out << ", INC=" << 2 * l.increments[step] << "\n*STATIC\n" << num(dt) << ", 1., " << num(1e-6 * dt) << ", "
          << num(dt) << "\n";
    } else {
      out << "\n*DYNAMIC, EXPLICIT\n, " << num(l.explicit_time[step]) << "\n";
    }
    if (step == 0) {
      if (!standard) {
        out << "*CONTACT\n*CONTACT INCLUSIONS\n";
        for (const char* p : kPairs) out << p << "-LOWER-TOP, " << p << "-UPPER-BOTTOM\n";
        out << "*CONTACT PROPERTY ASSIGNMENT\n";
        for (const char* p : kPairs) out << p << "-LOWER-TOP, " << p << "-UPPER-BOTTOM, MORTAR\n";
      }
      out << "*BOUNDARY\nSHEAR-BASE, ENCASTRE\nTENSION-BASE, ENCASTRE\nSHEAR-REF, 1, 1\nSHEAR-REF, 3, 6\n"
          << "TENSION-REF, 1, 6\n"
          << (standard ? "*CLOAD\n" : "*CLOAD, AMPLITUDE=PRESS\n") << "SHEAR-REF, 2, " << num(-force) << "\n";
    } else {
      out << (standard ? "*BOUNDARY\n" : "*BOUNDARY, AMPLITUDE=SLIDE\n") << "SHEAR-REF, 1, 1, " << num(l.slip)
          << "\nTENSION-REF, 2, 2, " << num(l.opening) << "\n";
    }
    if (standard)
      out << "*OUTPUT, FIELD, FREQUENCY=10\n*NODE OUTPUT\nU, RF\n*CONTACT OUTPUT\nCSTRESS, CDISP\n"
          << "*OUTPUT, HISTORY, FREQUENCY=1\n";
    else
      out << "*OUTPUT, FIELD, NUMBER INTERVAL=20\n*NODE OUTPUT\nU, RF\n*CONTACT OUTPUT\nCSTRESS\n"
          << "*OUTPUT, HISTORY, TIME INTERVAL=" << num(l.explicit_time[step] / 200) << "\n";
    out << "*NODE OUTPUT, NSET=SHEAR-REF\nU1, U2, RF1, RF2\n*NODE OUTPUT, NSET=TENSION-REF\nU2, RF2\n"
        << "*ENERGY OUTPUT\nALLSE, ALLPD, ALLWK" << (standard ? "" : ", ALLKE") << "\n*END STEP\n";
  }
}

}  // namespace mortar::harness
