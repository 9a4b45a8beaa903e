#pragma once
// Knot recognition every step, and the events it gives (issue 19, item 2).
//
// KnotTracker is handed the thread after each step — its node positions, the nodes where it is
// held (pierces), and each link's stretch — and keeps a reading of the knot in it
// (knot_recognition.h). Cost: the thread is read again only when a node has moved more than
// `moveTolerance` since the last reading, and then from the last reading's direction alone while
// that picture stays clear (knot_diagram.h: a sweep, O(n log n) in the links); the search over
// all directions is made only when it has not. A step in which nothing moved costs one pass
// over the nodes.
//
// A reading counts once the same throws (form, handedness, wraps of each) have been read
// `confirmReadings` times in a row, so one odd picture of a moving thread raises nothing. An
// Unknown reading (crossings no throw accounts for) never replaces a knot with throws: it is a
// picture the reader cannot explain, not a knot undone. Events, each once:
//  - ThrowFormed: the confirmed reading has more throws than before; one event per new throw.
//  - KnotTightened: a confirmed knot with at least one throw, with the thread pulled to at least
//    `tightStrain` (the largest link stretch: the strands pulled to tighten a knot carry the
//    thread's highest tension), that has stopped running along the thread: its place (the mean
//    of its throws', as arc length from node 0) has moved less than `seatDistance` over the last
//    `seatSteps` steps. A throw is run down to the wall under tension; until it sits there it is
//    being laid, not tightened, and its sliding is no slip. Its type, throws and tension (EA ×
//    stretch) are given, and its place is kept.
//  - KnotSlipped: a tightened knot that lost throws or its type (StructureLost), or whose place
//    along the thread moved by more than `slipDistance` while the tension stayed at or above
//    the tension it was tightened with (Sliding: the thread running through the knot). On a
//    stitch (anchors given, the throw nearest them around them) the place is the loop: the
//    thread from the throw's first passage through the stitch to its last. It slips when the
//    loop grows by more than `slipDistance` (the knot letting the stitch open); a loop that
//    shrinks is the throw still being run down, whatever its place does. A slipped
//    knot is tightened again once its ends have been let go (stretch below `tightStrain`) and
//    pulled again, or once a new throw has been added.
//
// Units: millimetres, seconds, grams; tension in g·mm/s² (µN).

#include "microsim/sim/suture/knot_recognition.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace microsim::sim::suture {

struct KnotTrackerDef {
  KnotRecognitionDef recognition;
  double moveTolerance = 0.01;  ///< mm a node may move before the thread is read again
  int confirmReadings = 2;      ///< readings in a row a new structure needs to count
  double tightStrain = 0.002;   ///< link stretch (relative) at which a knot counts as pulled tight
  /// EA of the thread (g·mm/s²): tension = EA × stretch. 10-0 nylon: EA/L ≈ 2.3e5 g/s² on 0.1 mm links
  double axialStiffness = 2.3e4;
  double slipDistance = 0.2;    ///< mm the knot may move along the thread while held tight
  /// mm the knot may move along the thread over seatSteps steps and count as stopped (seated):
  /// 0.02 mm in 3 steps at 100 Hz is under 0.7 mm/s, where a throw being run down moves mm/s
  double seatDistance = 0.02;
  int seatSteps = 3;
};

enum class KnotEventKind : std::uint8_t { ThrowFormed, KnotTightened, KnotSlipped };
enum class KnotSlipCause : std::uint8_t { StructureLost, Sliding };

struct KnotEvent {
  KnotEventKind kind = KnotEventKind::ThrowFormed;
  int step = 0;                             ///< as given to update()
  KnotType type = KnotType::None;           ///< the knot after the event (StructureLost: what is left)
  int throws = 0;                           ///< throws in the knot
  int throwIndex = -1;                      ///< ThrowFormed: which throw (0 = nearest the stitch)
  Handedness handedness = Handedness::Right;///< ThrowFormed: that throw's
  int wraps = 0;                            ///< ThrowFormed: that throw's
  double tension = 0.0;                     ///< g·mm/s² (µN), EA × the largest link stretch
  double slide = 0.0;                       ///< KnotSlipped: mm the knot moved along the thread
  KnotSlipCause cause = KnotSlipCause::StructureLost;  ///< KnotSlipped only
};

class KnotTracker {
 public:
  explicit KnotTracker(KnotTrackerDef def = {});

  /// Reads the thread after step `step`: `x` 3 by m node positions, `anchors` the held nodes,
  /// `linkStretch` the m − 1 links' relative stretch (may be empty: no tension). Returns the
  /// events of this step (also kept in events()).
  std::span<const KnotEvent> update(int step, const Points& x, std::span<const int> anchors,
                                    std::span<const double> linkStretch);

  /// The confirmed reading.
  const KnotReading& reading() const { return confirmed_; }
  bool tightened() const { return tight_.has_value(); }
  const std::vector<KnotEvent>& events() const { return events_; }
  /// Readings made (steps in which the thread had moved enough to be read).
  int readings() const { return readings_; }
  /// Of those, readings that had to search every direction.
  int searches() const { return searches_; }

 private:
  struct Tight {
    double place = 0.0;    // mm along the thread from node 0
    double tension = 0.0;  // g·mm/s²
    double loop = -1.0;    // mm (loop()); < 0: no stitch under the knot
  };
  void confirm(int step, const KnotReading& reading, double tension);
  double place(const KnotReading& reading) const;
  double loop(const KnotReading& reading) const;
  double arcAt(double parameter) const;

  KnotTrackerDef def_;
  Points read_{3, 0};               // the nodes as last read
  std::vector<int> readAnchors_;
  std::optional<Vec3> direction_;   // the last clear picture's direction
  KnotReading confirmed_;
  KnotReading candidate_;
  int candidateCount_ = 0;
  std::optional<Tight> tight_;
  std::vector<double> places_;      // the confirmed knot's place in the last seatSteps steps (mm)
  bool slipped_ = false;            // slipped, and the ends not let go since
  std::vector<double> arc_;         // arc length from node 0 to each node as last read (mm)
  std::vector<KnotEvent> events_;
  int readings_ = 0;
  int searches_ = 0;
};

}  // namespace microsim::sim::suture
