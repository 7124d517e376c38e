#include "output/inp_mesh.hpp"

#include <ostream>

#include "output/inp_deck.hpp"

namespace mortar::harness {

int InpMesh::add_node(double x, double y, double z) {
  nodes_.push_back({x, y, z});
  return static_cast<int>(nodes_.size());
}

int InpMesh::add_box(const std::string& elset, const std::array<double, 3>& lo, const std::array<double, 3>& hi,
                     const std::array<int, 3>& n) {
  const int first_node = static_cast<int>(nodes_.size()) + 1;
  auto at = [&](int d, int i) { return i == n[d] ? hi[d] : lo[d] + (hi[d] - lo[d]) * i / n[d]; };
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i) add_node(at(0, i), at(1, j), at(2, k));
  auto node = [&](int i, int j, int k) { return first_node + i + (n[0] + 1) * (j + (n[1] + 1) * k); };
  MeshBox b{elset, static_cast<int>(elements_.size()) + 1, first_node, n};
  // C3D8 order: the z- face counter-clockwise seen from z+, then the z+ face.
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        elements_.push_back({node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                             node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                             node(i, j + 1, k + 1)});
  boxes_.push_back(b);
  return static_cast<int>(boxes_.size()) - 1;
}

std::vector<ElementFace> InpMesh::side(int b, BoxSide s) const {
  const MeshBox& box = boxes_[static_cast<size_t>(b)];
  const auto& n = box.n;
  std::vector<ElementFace> out;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const bool on = (s == BoxSide::xmin && i == 0) || (s == BoxSide::xmax && i == n[0] - 1) ||
                        (s == BoxSide::ymin && j == 0) || (s == BoxSide::ymax && j == n[1] - 1) ||
                        (s == BoxSide::zmin && k == 0) || (s == BoxSide::zmax && k == n[2] - 1);
        if (on) out.push_back({box.first_element + i + n[0] * (j + n[1] * k), static_cast<int>(s)});
      }
  return out;
}

std::vector<int> InpMesh::bottom_nodes(int b) const {
  const MeshBox& box = boxes_[static_cast<size_t>(b)];
  std::vector<int> out;
  for (int k = 0; k <= box.n[2]; ++k)
    for (int i = 0; i <= box.n[0]; ++i) out.push_back(box.first_node + i + (box.n[0] + 1) * (box.n[1] + 1) * k);
  return out;
}

void InpMesh::write_nodes(std::ostream& out) const {
  out << "*NODE\n";
  for (size_t i = 0; i < nodes_.size(); ++i)
    out << i + 1 << ", " << exact_decimal(nodes_[i][0]) << ", " << exact_decimal(nodes_[i][1]) << ", "
        << exact_decimal(nodes_[i][2]) << "\n";
}

void InpMesh::write_elements(std::ostream& out, const std::string& type, const std::vector<int>& which) const {
  for (size_t b = 0; b < boxes_.size(); ++b) {
    bool wanted = which.empty();
    for (int w : which) wanted = wanted || w == static_cast<int>(b);
    if (!wanted) continue;
    const MeshBox& box = boxes_[b];
    out << "*ELEMENT, TYPE=" << type << ", ELSET=" << box.elset << "\n";
    const int count = box.n[0] * box.n[1] * box.n[2];
    for (int e = box.first_element; e < box.first_element + count; ++e) {
      out << e;
      for (int v : elements_[static_cast<size_t>(e - 1)]) out << ", " << v;
      out << "\n";
    }
  }
}

void write_set(std::ostream& out, const std::string& keyword_line, const std::vector<int>& members) {
  out << keyword_line << "\n";
  for (size_t i = 0; i < members.size(); ++i)
    out << members[i] << (i + 1 == members.size() || i % 16 == 15 ? "\n" : ", ");
}

void write_element_surface(std::ostream& out, const std::string& name, const std::vector<ElementFace>& faces) {
  out << "*SURFACE, TYPE=ELEMENT, NAME=" << name << "\n";
  for (const auto& [element, face] : faces) out << element << ", S" << face << "\n";
}

}  // namespace mortar::harness
