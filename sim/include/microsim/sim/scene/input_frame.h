#pragma once
// What the hands do at one instant: the only input the simulation has. Trackers, the
// mouse/keyboard emulation and recordings all produce InputFrames; the stepper consumes
// them; a recording stores them verbatim, so a replay feeds the stepper the same bits.
//
// Poses are in the scene frame (mm) once calibration has been applied; a tracker source
// produces them in its own frame and the calibration maps them (DESIGN.md §Data flow).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>

namespace microsim::sim {

/// The two hands of the trainee. Each holds one instrument at a time.
enum class Hand : std::uint8_t { Left = 0, Right = 1 };
inline constexpr int kHandCount = 2;

/// The instrument a hand holds. The values are stored in recordings: append only.
enum class Instrument : std::uint8_t {
  None = 0,
  Forceps = 1,       ///< micro-forceps: grabs tissue, needle and suture
  NeedleHolder = 2,  ///< holds the needle (a forceps with a needle grip)
  Scalpel = 3,
  Scissors = 4,      ///< microscissors: cut the thread where they close (tools/microscissors.h)
};

struct HandInput {
  Instrument instrument = Instrument::Forceps;
  bool tracked = false;  ///< false: the source lost this hand; the tool stays where it was
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< tool tip, scene frame (mm)
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< tool frame → scene frame
  double closure = 0.0;  ///< 0 = open, 1 = closed (forceps jaws, needle-holder grip)

  bool operator==(const HandInput& o) const {
    return instrument == o.instrument && tracked == o.tracked && position == o.position &&
           orientation.coeffs() == o.orientation.coeffs() && closure == o.closure;
  }
};

struct InputFrame {
  double time = 0.0;  ///< s since the start of the attempt
  std::array<HandInput, kHandCount> hands{};

  HandInput& hand(Hand h) { return hands[static_cast<int>(h)]; }
  const HandInput& hand(Hand h) const { return hands[static_cast<int>(h)]; }
  bool operator==(const InputFrame& o) const = default;
};

/// Why an InputFrame may not reach the simulation. Sources count rejections by reason.
enum class InputRejection : std::uint8_t {
  NonFinite,          ///< NaN or Inf in a position, orientation, closure or time
  NotUnitRotation,    ///< the orientation is not a unit quaternion (|q| off by > 1e-6)
  ClosureOutOfRange,  ///< closure outside [0, 1]
  TimeBackwards,      ///< time earlier than the previous accepted frame's
};

/// Checks one frame on its own (time order needs the previous frame; see validateSequence).
/// Returns true and leaves `why` alone when the frame is usable.
bool validateFrame(const InputFrame& frame, InputRejection& why);

/// validateFrame plus time order against the previous accepted frame's time.
bool validateSequence(const InputFrame& frame, double previousTime, InputRejection& why);

}  // namespace microsim::sim
