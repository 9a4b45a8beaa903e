#include "fuzz/fuzz_targets.h"

#include <array>

namespace microsim::fuzz {

std::span<const Target> targets() {
  static constexpr std::array kTargets = {
      Target{"scene", &fuzzSceneFile},
      Target{"spring-scene", &fuzzSpringScene},
      Target{"recording", &fuzzRecording},
      Target{"igtl", &fuzzIgtlStream},
      Target{"rubric", &fuzzRubric},
      Target{"setup-profile", &fuzzSetupProfile},
      Target{"lesson", &fuzzLesson},
  };
  return kTargets;
}

}  // namespace microsim::fuzz
