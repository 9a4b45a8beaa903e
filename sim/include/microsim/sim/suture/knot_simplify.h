#pragma once
// Reidemeister moves on a Gauss word (knot_diagram.h): remove the crossings that tie nothing.
//
// The word runs from one end of the thread to the other, and no move passes from its last
// passage to its first: the ends are held (the needle and the tail are in the hands; joined far
// outside they would be free to turn about each other, and a throw — two strands twisted about
// the stitch — would untwist, as a single throw does when its ends are let go and turned).
// Two moves are made until neither applies:
//  - RI, a kink: a crossing passed twice in a row (nothing between its two passages) is a loop
//    that can be untwisted; it goes.
//  - RII, an overlay: two crossings passed one after the other, both over (or both under), and
//    passed one after the other again elsewhere, with opposite signs, are one strand lying across
//    another; it slides off and both go.
// An anchor mark between two passages makes them not consecutive: a loop round a pierce cannot
// be untwisted, nor a strand slid across it.
//
// RIII (moving a strand across a crossing) is not made: it keeps the crossing count, and finding
// the sequence of RIII moves that lets RI/RII go on is a search the per-step budget does not
// allow. Diagrams that need it keep their crossings and read as unknown (knot_recognition.h).
// Each move removes one or two crossings, so there are at most as many rounds as crossings, each
// linear in the word's length.

#include "microsim/sim/suture/knot_diagram.h"

#include <vector>

namespace microsim::sim::suture {

/// Counts of the moves made.
struct ReidemeisterCount {
  int kinks = 0;     ///< RI moves
  int overlays = 0;  ///< RII moves
};

/// Simplifies `word` in place by RI and RII moves; `crossings` gives each crossing's sign.
ReidemeisterCount simplifyGaussWord(std::vector<GaussEntry>& word,
                                    const std::vector<KnotCrossing>& crossings);

/// How many crossings `word` still passes (each crossing is passed twice).
int crossingCount(const std::vector<GaussEntry>& word);

}  // namespace microsim::sim::suture
