#pragma once
// A 3D mouse (3Dconnexion SpaceNavigator, SpaceMouse, ...) as a tracker source, through
// spacenavd and libspnav (Debian: spacenavd, libspnav-dev). The cap moves and turns the active
// forceps at a rate, button 0 held closes its jaws and button 1 switches the hand
// (spacenav_mapping.h); frames are in the scene frame (rate_tool_source.h).
//
// start() connects to the daemon (spacenav_link.h says where it looks). Without a daemon it
// emits linkDown with status().lastError saying so and produces nothing; when the daemon goes
// away the hands are marked untracked (the tools stay), and linkDown follows. Events are read
// on the owner's thread as the daemon's socket becomes readable.

#include "tracking/rate_tool_source.h"
#include "tracking/spacenav_link.h"

#include <QPointer>

class QSocketNotifier;

namespace microsim::tracking {

class SpacenavSource : public RateToolSource {
  Q_OBJECT

 public:
  explicit SpacenavSource(QObject* parent = nullptr);
  ~SpacenavSource() override;

  void start() override;
  void stop() override;

  void setScale(const SpacenavScale& scale) { scale_ = scale; }

  /// Reads every pending event now (what the socket's readability triggers).
  void readPending();

 private:
  void apply(const SpacenavEvent& event);
  void closeLink();

  SpacenavLink link_;
  SpacenavScale scale_;
  QPointer<QSocketNotifier> notifier_;
};

}  // namespace microsim::tracking
