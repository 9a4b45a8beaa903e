#pragma once
// The connection to spacenavd through libspnav, and nothing else: libspnav's header pulls in
// Xlib (its macros would clash with Qt and with our enums), so it is included by
// spacenav_link.cpp alone, which the build compiles outside the unity batches.
//
// libspnav keeps one connection per process (its state is global): one SpacenavLink at a
// time. It connects over spacenavd's AF_UNIX socket: $SPNAV_SOCKET if set, else the `socket`
// line of /etc/spnavrc, else /var/run/spnav.sock.

#include "tracking/spacenav_mapping.h"

#include <optional>

namespace microsim::tracking {

struct SpacenavEvent {
  enum class Kind { Motion, Button } kind = Kind::Motion;
  SpacenavMotion motion;  ///< Motion
  int button = 0;         ///< Button: the device's button number
  bool pressed = false;   ///< Button: pressed (true) or released
};

class SpacenavLink {
 public:
  SpacenavLink() = default;
  ~SpacenavLink();
  SpacenavLink(const SpacenavLink&) = delete;
  SpacenavLink& operator=(const SpacenavLink&) = delete;

  /// Connects to the daemon; false when it is not running (or another link is open).
  bool open();
  void close();
  bool isOpen() const { return open_; }
  /// The socket to watch for readability; -1 when closed.
  int fd() const;
  /// The next pending motion or button event without blocking; nullopt when none is pending
  /// (device and configuration events are skipped).
  std::optional<SpacenavEvent> poll();
  /// True when the daemon has closed the connection (checked without consuming anything).
  bool peerClosed() const;

 private:
  bool open_ = false;
};

}  // namespace microsim::tracking
