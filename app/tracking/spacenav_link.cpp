#include "tracking/spacenav_link.h"

#include <sys/socket.h>

// last: Xlib's macros (None, Bool, Status, ...) must not reach any header above
#include <spnav.h>

namespace microsim::tracking {

SpacenavLink::~SpacenavLink() { close(); }

bool SpacenavLink::open() {
  if (open_) return true;
  open_ = spnav_open() == 0;
  return open_;
}

void SpacenavLink::close() {
  if (!open_) return;
  spnav_close();
  open_ = false;
}

int SpacenavLink::fd() const { return open_ ? spnav_fd() : -1; }

std::optional<SpacenavEvent> SpacenavLink::poll() {
  // libspnav would poll an unopened descriptor (-1) rather than refuse
  if (!open_) return std::nullopt;
  spnav_event raw{};
  while (spnav_poll_event(&raw) != 0) {
    SpacenavEvent event;
    if (raw.type == SPNAV_EVENT_MOTION) {
      event.kind = SpacenavEvent::Kind::Motion;
      event.motion = {raw.motion.x,  raw.motion.y,  raw.motion.z,     raw.motion.rx,
                      raw.motion.ry, raw.motion.rz, raw.motion.period};
      return event;
    }
    if (raw.type == SPNAV_EVENT_BUTTON) {
      event.kind = SpacenavEvent::Kind::Button;
      event.button = raw.button.bnum;
      event.pressed = raw.button.press != 0;
      return event;
    }
  }
  return std::nullopt;
}

bool SpacenavLink::peerClosed() const {
  if (!open_) return true;
  char byte = 0;
  return ::recv(spnav_fd(), &byte, 1, MSG_PEEK | MSG_DONTWAIT) == 0;
}

}  // namespace microsim::tracking
