#pragma once
// How the viewport presents the microscope's two eyes.

#include <cstdint>

namespace microsim::gui {

enum class StereoMode : std::uint8_t {
  Mono,        ///< one eye, the default
  QuadBuffer,  ///< left/right back buffers; only when the surface format has StereoBuffers
               ///< (otherwise the viewport falls back to Anaglyph)
  Anaglyph,    ///< red (left eye) / cyan (right eye) glasses
  SideBySide,  ///< left eye in the left half, right eye in the right half (HMDs, mirror rigs)
};

}  // namespace microsim::gui
