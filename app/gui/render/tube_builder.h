#pragma once
// A smooth tube around a polyline (the suture and the needle): the nodes are refined with a
// centripetal-free uniform Catmull–Rom spline, and a ring of `sides` vertices is swept along
// it with parallel-transported frames (no twist), each vertex with its outward normal; the
// two ends are closed with flat caps. A polyline with broken links becomes one tube per
// intact run. Built on the GUI thread from each snapshot; reuses the mesh's buffers.
//
// Units: millimetres.

#include "gui/shaded_mesh.h"

#include <cstdint>
#include <vector>

namespace microsim::gui {

struct TubeStyle {
  float radius = 0.02f;   ///< mm
  int sides = 6;          ///< vertices around
  int subdivisions = 2;   ///< spline points per link (1: the polyline itself)
};

/// Appends the tube over nodes [first, last] of `xyz` (3 floats per node) to `mesh`. `alive`
/// (one per link i→i+1, may be empty: all intact) splits the tube where a link is 0.
void appendTube(const std::vector<float>& xyz, int first, int last,
                const std::vector<std::uint8_t>& alive, const TubeStyle& style, ShadedMesh& mesh);

}  // namespace microsim::gui
