// The mesh part of the harness's Abaqus decks: boxes of hexahedra (one box
// per block), reference nodes, and the element faces on each side of a box
// for element-based *SURFACE definitions; written as *NODE, *ELEMENT,
// *NSET, *ELSET and *SURFACE. Every block gets its own nodes (blocks touch
// only through contact). Faces follow C3D8's numbering: S1 z-, S2 z+,
// S3 y-, S4 x+, S5 y+, S6 x-.
#pragma once

#include <array>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace mortar::harness {

enum class BoxSide { zmin = 1, zmax = 2, ymin = 3, xmax = 4, ymax = 5, xmin = 6 };

struct MeshBox {
  std::string elset;          // the box's elements
  int first_element = 0;      // its elements: first_element .. first_element + nx·ny·nz − 1
  int first_node = 0;         // its nodes: x fastest, then y, then z
  std::array<int, 3> n{};     // divisions along x, y, z
};

// One element face of a *SURFACE, TYPE=ELEMENT: (element, face number 1..6).
using ElementFace = std::pair<int, int>;

class InpMesh {
 public:
  // A box [lo, hi] cut into n[0]×n[1]×n[2] hexahedra; returns its index.
  int add_box(const std::string& elset, const std::array<double, 3>& lo, const std::array<double, 3>& hi,
              const std::array<int, 3>& n);
  // A node of its own (a rigid body's reference node); returns its number.
  int add_node(double x, double y, double z);
  const MeshBox& box(int b) const { return boxes_[static_cast<size_t>(b)]; }
  // The element faces of box b on one side.
  std::vector<ElementFace> side(int b, BoxSide s) const;
  // The nodes of box b on the plane y = its lowest y.
  std::vector<int> bottom_nodes(int b) const;
  int elements() const { return static_cast<int>(elements_.size()); }

  // *NODE with every node.
  void write_nodes(std::ostream& out) const;
  // *ELEMENT, TYPE=type, ELSET=<box elset> for the boxes `which` (all if empty).
  void write_elements(std::ostream& out, const std::string& type, const std::vector<int>& which = {}) const;

 private:
  std::vector<std::array<double, 3>> nodes_;
  std::vector<std::array<int, 8>> elements_;
  std::vector<MeshBox> boxes_;
};

// *NSET or *ELSET data lines: at most 16 numbers a line (the Abaqus limit).
void write_set(std::ostream& out, const std::string& keyword_line, const std::vector<int>& members);
// *SURFACE, TYPE=ELEMENT, NAME=name with one face a line.
void write_element_surface(std::ostream& out, const std::string& name, const std::vector<ElementFace>& faces);

}  // namespace mortar::harness
