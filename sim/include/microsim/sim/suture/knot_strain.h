#pragma once
// A knot drawn past tight breaks the thread in the knot, as nylon does, instead of passing
// through itself.
//
// Why. The thread is inextensible: between two grips its links keep their lengths, and the
// grips' break check (suture_constraints.h) compares the straight path between them with the
// thread's arc. A knot uses thread, so its ends never come that far apart: drawn on past tight,
// the knot shrinks until the strands, held a diameter apart by the self-contact pass, can no
// longer keep both their contact and their lengths. The contact wins for a while (the knot's
// links stand 5 % over length, then 10, 20, ... 96 % over 17 steps in a square knot drawn 3.4 mm
// a side past tight) and then the length restore drags the strands through each other: the
// knot came undone with no event (session 16's finding).
//
// The rule. A link the last self-contact pass of a substep touched, with another strand
// against it from the side (pressed on another, as in a knot), and that stands more than
// knotBreakStretch (10 %) over its length carries the knot's tension. Held so for kKnotBreakSeconds
// in a row, the thread breaks at the most stretched of those links (SutureEventKind::Break), and
// every hold starts again. The limit is twice the grips' breakStretch: a surgeon's knot drawn tight
// presses its double throw with links 3-5 % over for several steps, and at 5 % it broke 0.5 mm a
// side after it was tightened, long before it was crushed; at 10 % the square, granny and surgeon's
// knots of the knot scene break at 3.50-3.54 mm a side, a step or five before they passed through
// themselves (3.56-3.59 mm). The hold tells a knot drawn past tight (its links stay over
// length while the hands pull) from a strand pushed off another in one substep (a fast hand
// crossing the thread over itself stretches a short link for a substep or two, then the
// lengths are restored). A knot under a working load (its links a few per cent over at most)
// never breaks; a slack thread never does.
//
// Units: millimetres, seconds.

#include "microsim/sim/suture/suture_constraints.h"
#include "microsim/sim/suture/suture_model.h"

#include <cstdint>
#include <optional>
#include <span>

namespace microsim::sim::suture {

/// s: how long a link must stay past knotBreakStretch in a pressed strand before it breaks.
inline constexpr double kKnotBreakSeconds = 0.03;

/// Updates state.heldPastBreak for a substep of `seconds` (sizes it to the links on first
/// use) from `pressed` (per node: the last self-contact pass moved it; pairs fewer than `skip`
/// links apart are not contacts), and returns the link
/// that breaks, if one does; the caller marks it broken. Only links between two of their
/// piece's grips or pierces count: a piece with a free end carries no knot's tension (the
/// pieces a break leaves spring back, and their strands pushed apart stretch links).
std::optional<int> findKnotBreak(const SutureModel& model, SutureState& state,
                                 std::span<const Grip> grips, std::span<const std::uint8_t> pressed,
                                 int skip, double seconds);

}  // namespace microsim::sim::suture
