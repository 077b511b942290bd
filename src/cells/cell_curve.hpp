// An order of a grid's cells along a space-filling curve: the box of cells is halved across its
// longest side, recursively, and the halves are visited one after the other (a Morton order that
// works for any counts, with no cell skipped or visited twice and no table).  Cells close on the
// curve are close in space, so particles numbered in this order keep their neighbours' records a
// few cache lines and one huge page away (Simulation::renumber).
#pragma once

#include <array>
#include <cstdint>

namespace granule {

namespace detail {
template <int D, typename Visit>
void visit_cell_box(std::array<int, D> lowest, std::array<int, D> highest, Visit& visit) {
  int longest = 0;
  for (int a = 1; a < D; ++a) {
    if (highest[a] - lowest[a] > highest[longest] - lowest[longest]) longest = a;
  }
  const int length = highest[longest] - lowest[longest];
  if (length <= 0) return;
  if (length == 1) {  // then every side is 1: one cell
    visit(lowest);
    return;
  }
  std::array<int, D> middle = highest;
  middle[longest] = lowest[longest] + length / 2;
  visit_cell_box<D>(lowest, middle, visit);
  std::array<int, D> upper = lowest;
  upper[longest] = middle[longest];
  visit_cell_box<D>(upper, highest, visit);
}
}  // namespace detail

// visit(coordinates) for every cell of a grid of counts[0] × counts[1] (× counts[2]) cells, along
// the curve.  The recursion is as deep as log2 of the number of cells.
template <int D, typename Visit>
void for_each_cell_along_curve(const std::array<int, D>& counts, Visit&& visit) {
  std::array<int, D> lowest{};
  detail::visit_cell_box<D>(lowest, counts, visit);
}

}  // namespace granule
