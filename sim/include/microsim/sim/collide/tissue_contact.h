#pragma once
// Tissue against tissue: the two cut ends against each other, a wall against the opposite
// wall of its own lumen (so a back-wall catch is something the needle has to push through,
// and a collapsed lumen stays a lumen). Penalty contact, as one-sided point springs
// (point_spring.h) that the tissue solver minimises with the links:
//
//   for a surface node p and a face (a, b, c) it may touch, with q = u a + v b + w c the
//   closest point of the face and n the face's normal (outward: the vessel's triangles are
//   wound so that it points out of the wall), the term keeps n·(p − q) ≥ thickness. Both
//   sides move (weights 1, −u, −v, −w).
//
// Which pairs may touch. A node and a face never collide when a corner of the face lies within
// selfDistance of the node at rest, or at most three links from it: they are the same stretch
// of wall (the other layer of it, the next ring, however coarse the mesh), and what keeps
// them apart is the links. (By rest distance alone, 0.3 mm, a wall pulled until it buckled
// pressed its inner surface on its outer one a ring along, 0.5 mm apart at rest in the
// shipped vessels, and those terms held it folded: solves at their iteration limit, 0.3 s a
// step. A rest distance past the ring spacing would part the two cut ends, 0.5 mm apart.)
// Everything else, within one body or across bodies, may: the two cut ends, 0.5 mm apart and
// joined by no link, and a wall against the opposite wall of its lumen. So no body labels are
// needed, and a mesh with one lumen or ten is treated alike.
//
// When. The scene detects at the start of the tissue solve (every node within `reach` of a
// face gets a term, pressed or not: one-sided terms cost nothing until pressed), solves, and
// looks again for nodes that the solve carried into a face without a term (violations); those
// are added and the solve repeats, at most a few rounds (scene.cpp).
//
// Cost. A uniform grid of the faces' boxes, grown by reach + slack (slack = reach; cell = the
// largest of the mean edge and 2·reach), as (cell, face) entries filed by a hash of the cell,
// each bucket in face order: O(F) to build for F faces, by a counting sort. (A sorted list
// before: its comparison sort, branching unpredictably, made a query that rebuilt the grid on
// the shipped vessels cost 1.6–2.3 ms where it now costs 0.5 ms, thread CPU, min of 20.) It is
// rebuilt only once some node has moved more than slack/2 since it was
// built: until then a node within reach of a face still lies in that face's grown box (each
// has moved at most slack/2). A query is O(N) for N surface nodes. The faces each node
// never meets are listed once, at construction (a node's own stretch of wall is three links
// deep, so the rule is one look-up a face instead of six), sorted, and walked along with the
// cell's faces, which come in face order too (a binary search for each candidate instead made
// a query at the stitch's positions cost 0.40 ms where it costs 0.17 ms, thread CPU, no grid
// rebuilt, min of 20), and the faces' boxes are taken once
// a query, not once for every node that looks at them: over the shipped stitch's replay the
// contact queries went from 1.26 G instructions (27 % of the whole) to 0.70 G (callgrind),
// with the same pairs. The scene looks again only when the tissue has moved, and a query
// returns at once, with no pair, while the tissue lies within a quarter of the reach of where a
// query last found every surface node clear of every face it may meet by 1.5 reach (the
// grid's candidates cover that far): a node and a face have each moved less than reach/4 since,
// so they are still more than a reach apart. Still steps (the tissue creeping by tenths of a
// micrometre while the thread settles) cost 3 M instructions of contact queries each before,
// one pass over the nodes now (a few thousand), with the same pairs; the shipped stitch's
// replay went from 4.75 G instructions to 3.81 G (callgrind).
//
// Units: mm, stiffness g/s².

#include "microsim/sim/mesh/point_spring.h"
#include "microsim/sim/mesh/spring_model.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace microsim::sim::collide {

struct TissueContactParams {
  double stiffness = 0.0;     ///< g/s²; 0 = 20 × the stiffest link
  double thickness = 0.01;    ///< mm: the separation contact keeps
  double reach = 0.1;         ///< mm: a node this near a face is watched during a solve
  double selfDistance = 0.3;  ///< mm: node and face this near at rest never collide
};

/// The contact stiffness when none is given: 20 × the stiffest link (g/s²), stiff enough that
/// a contact yields far less than a link stretches.
double defaultContactStiffness(const SpringModel& tissue);

/// One node against one face.
struct TissueContactPair {
  int node = -1;
  int face = -1;
  bool operator==(const TissueContactPair&) const = default;
};

class TissueContact {
 public:
  TissueContact(const SpringModel& tissue, const TissueContactParams& params);

  /// Every (node, face) pair within reach at positions x, at most one face per node, in node
  /// order: the nearest, where an edge or a corner makes several about as near the one the node
  /// faces most squarely (distance × (2 − |n·(p − q)| / |p − q|) smallest), so that a lip
  /// pressed onto the other end's cut face meets that face, not the hull it would slide along.
  std::vector<TissueContactPair> near(const Points& x) const;
  /// The pairs whose node lies less than half the thickness in front of (or behind) the face.
  std::vector<TissueContactPair> violations(const Points& x) const;
  /// The one-sided spring that keeps `pair` apart, its normal frozen at positions x.
  PointSpring spring(const TissueContactPair& pair, const Points& x) const;

  double stiffness() const { return stiffness_; }
  /// The nodes on the tissue's faces, in order: the ones that can touch anything.
  const std::vector<int>& surfaceNodes() const { return surfaceNodes_; }
  const TissueContactParams& params() const { return params_; }

 private:
  /// The closest eligible face to node i within `radius` (−1 for none), its signed distance;
  /// `nearest` is lowered to the distance of any eligible face within `watch` (≥ radius).
  std::pair<int, double> closestFace(const Points& x, int node, double radius, double watch,
                                     double& nearest) const;
  /// Whether no node can be within reach of a face at x, by the last clear query (above).
  bool stillClear(const Points& x) const;
  /// The pairs (node, its closest eligible face within reach) whose signed distance is below
  /// `signedDistance` (mm).
  std::vector<TissueContactPair> pairsCloserThan(const Points& x, double signedDistance) const;
  void buildGrid(const Points& x) const;
  std::int64_t cellKey(int ix, int iy, int iz) const;
  /// The grid's bucket of a cell's key.
  std::size_t gridBucket(std::int64_t key) const;

  const SpringModel& tissue_;
  TissueContactParams params_;
  double stiffness_ = 0.0;
  double cell_ = 1.0;
  std::vector<int> surfaceNodes_;
  std::vector<std::vector<int>> ownFaces_;  // per surface node: the faces it never meets, sorted
  // per face, the box of its corners at the positions of the query running (3 by F)
  mutable Points faceLow_{3, 0};
  mutable Points faceHigh_{3, 0};
  // the grid, rebuilt for each query at its positions: (cell, face) filed by a hash of the cell
  // into 2^gridBits_ buckets, bucket b's entries from gridStart_[b], in face order
  mutable std::vector<std::pair<std::int64_t, int>> grid_;
  mutable std::vector<int> gridStart_, gridFill_;
  mutable std::vector<Eigen::Vector3i> gridBoxes_;  ///< per face, its lowest and highest cell
  mutable int gridBits_ = 1;
  mutable Points gridX_{3, 0};  ///< the positions the grid was built at
  mutable Points clearX_{3, 0};  ///< where the last query found every node clear (else empty)
  mutable bool gridLeftFaceOut_ = false;  ///< a face torn too far apart to grid: never "clear"
};

}  // namespace microsim::sim::collide
