#pragma once
// Which knot the thread is tied in, read from its geometry (issue 19, item 2).
//
// 1. Look. The thread (its node positions, the stitch's pierces as anchors) is projected along
//    several directions fixed in its own principal frame (knot_diagram.h); each picture gives a
//    Gauss word, simplified by RI and RII moves (knot_simplify.h). Only clear pictures — no
//    grazing crossings, no three strands through one point, no strand seen end-on, ends that
//    leave the picture without crossing it — are read, and they vote: the reading most of them
//    give wins (ties to the clearer picture); where some pictures are fully explained by the
//    rules below, only those vote, since one RI and RII could not clear only needed RIII. Near-degenerate directions are thereby passed over
//    instead of read wrongly; where one looks from changes how many half turns a twist and its
//    tails show, the majority does not; and a rigid rotation of the thread changes nothing.
// 2. The stitch. The stretch between the first and last anchor lies in the tissue; crossings
//    with it are dropped. Around it, the two strands (needle side and tail side) can only twist:
//    a crossing whose two passages have nothing but the anchors (and crossings already taken)
//    between them is a half twist of the strands next to the stitch. Taken innermost first,
//    half twists of one sign whose strands go over and under by turns are one throw of
//    half-twists/2 wraps (a half knot: 2 crossings; a surgeon's double throw: 4); a lone half
//    twist is the strands laid across each other, no throw.
// 3. In one strand. What is left is cut into blocks: the shortest stretches of the word in
//    which every crossing is passed twice, taken out one by one (the prime pieces of a knot
//    tied in a row). A block of 2w + 1 crossings of one sign passed over and under by turns is
//    an overhand throw of w wraps: w = 1 the overhand knot (a trefoil once the ends are joined),
//    w = 2 the double overhand.
// 4. Hitches. A throw or block in which one strand runs straight (chord ≥ `straightness` of its
//    arc) while the other winds round it (chord ≤ `wrapped` of its arc) is a hitch: the knot can
//    slide along the straight strand.
// 5. Name it. Handedness is the sign of a throw's crossings: right-handed (+1) or left-handed
//    (−1), as the right- and left-handed trefoil. Two throws of opposite handedness in a row
//    lock (square); two of the same do not (granny); a double throw followed by throws that
//    alternate is the surgeon's knot; any hitch makes a slip knot. Crossings no rule accounts
//    for make the knot Unknown, never a guess.
//
// Not recognised: knots whose simplest picture needs RIII moves to reach (they read as Unknown
// until the thread is pulled tighter), throws pressed so hard into one another that their
// crossings interleave, two throws of one sign twisted about the stitch with nothing between
// them (they read as one throw of two wraps: the geometry is the same), and which throw was
// tied first when the knot lies in one strand away from any anchor (they are listed along the
// thread).

#include "microsim/sim/suture/knot_diagram.h"

#include <cstdint>
#include <span>
#include <vector>

namespace microsim::sim::suture {

enum class Handedness : std::uint8_t { Left, Right };

enum class ThrowForm : std::uint8_t {
  Twist,     ///< the two strands twisted about the stitch: 2 crossings per wrap
  Overhand,  ///< a block in one strand: 2·wraps + 1 crossings
  Hitch,     ///< one strand straight, the other wound round it
};

enum class KnotType : std::uint8_t {
  None,         ///< no throw, nothing left unexplained
  SingleThrow,  ///< one throw: a half knot round the stitch, an overhand in one strand
  Square,       ///< single throws of alternating handedness
  Granny,       ///< two throws in a row of the same handedness: it slips
  Surgeons,     ///< a double throw, then throws of alternating handedness (2 + 1)
  SlipKnot,     ///< one strand straight, the other hitched round it
  Unknown,      ///< crossings that no throw accounts for
};

struct KnotThrow {
  ThrowForm form = ThrowForm::Twist;
  Handedness handedness = Handedness::Right;
  int wraps = 1;
  int crossings = 0;       ///< crossings it is made of
  double position = 0.0;   ///< curve parameter: the mean of its passages (node index + fraction)
  double first = 0.0;      ///< curve parameter of its passage nearest node 0
  double last = 0.0;       ///< curve parameter of its passage farthest from node 0
};

struct KnotRecognitionDef {
  /// Directions to look from; empty: knotViewDirections() of the thread.
  std::vector<Vec3> directions;
  double clearQuality = 0.5;  ///< a hinted picture at least this clear is taken without a search
  double straightness = 0.97; ///< chord/arc at or above which a strand through a throw is straight
  double wrapped = 0.9;       ///< chord/arc at or below which a strand winds round the other
  /// links a strand's stretch through a throw is extended by, each way, to judge its shape
  double shapePadding = 2.0;
  /// crossings left after RI/RII beyond which the thread is a tangle, read as Unknown unexamined
  /// (the block search is cubic in them)
  int maxCrossings = 64;
};

struct KnotReading {
  KnotType type = KnotType::None;
  std::vector<KnotThrow> throws;  ///< nearest the stitch first; without anchors along the thread
  int rawCrossings = 0;           ///< in the chosen picture
  int crossings = 0;              ///< left after RI and RII
  int unexplained = 0;            ///< of those, crossings no throw accounts for
  Vec3 direction = Vec3::UnitZ(); ///< the picture it was read from
  double quality = 0.0;           ///< that picture's clearness (knot_diagram.h)
};

/// Reads one picture (made by projectKnot with the same `x` and anchors).
KnotReading readKnotDiagram(const Points& x, const KnotDiagram& diagram,
                            const KnotRecognitionDef& def = {});

/// The knot in `x` (3 by m), held at the nodes `anchors` (may be empty): the reading most clear
/// pictures from def.directions give (the clearest picture's when none is clear). With `hint`
/// (the direction of a previous reading), that picture is taken alone when it is at least
/// def.clearQuality clear and its ends cross nothing.
/// The same throws (form, handedness, wraps), one for one, and the same name.
bool sameKnotReading(const KnotReading& a, const KnotReading& b);

KnotReading recogniseKnot(const Points& x, std::span<const int> anchors,
                          const KnotRecognitionDef& def = {}, const Vec3* hint = nullptr);

}  // namespace microsim::sim::suture
