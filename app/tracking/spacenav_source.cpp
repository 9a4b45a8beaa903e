#include "tracking/spacenav_source.h"

#include <QSocketNotifier>

namespace microsim::tracking {

SpacenavSource::SpacenavSource(QObject* parent) : RateToolSource(parent) {}

SpacenavSource::~SpacenavSource() { closeLink(); }

void SpacenavSource::start() {
  if (running()) return;
  if (!link_.open()) {
    linkFailed(tr("No 3D mouse: spacenavd, the 3D mouse's daemon, is not running or cannot be reached "
                  "(install and start spacenavd, then try again)."));
    return;
  }
  notifier_ = new QSocketNotifier(static_cast<qintptr>(link_.fd()), QSocketNotifier::Read, this);
  connect(notifier_, &QSocketNotifier::activated, this, &SpacenavSource::readPending);
  linkUp();
}

void SpacenavSource::stop() {
  closeLink();
  linkClosed();
}

void SpacenavSource::closeLink() {
  delete notifier_;
  link_.close();
}

void SpacenavSource::readPending() {
  if (!running()) return;
  bool any = false;
  while (const std::optional<SpacenavEvent> event = link_.poll()) {
    any = true;
    apply(*event);
  }
  if (!any && link_.peerClosed()) {
    closeLink();
    linkFailed(tr("The 3D mouse's daemon (spacenavd) closed the connection."));
  }
}

void SpacenavSource::apply(const SpacenavEvent& event) {
  if (event.kind == SpacenavEvent::Kind::Motion) {
    drive(spacenavCommand(event.motion, scale_), spacenavStep(event.motion, scale_));
    return;
  }
  switch (spacenavButtonAction(event.button)) {
    case SpacenavButtonAction::HoldJaws: setClosure(activeHand(), event.pressed ? 1.0 : 0.0); break;
    case SpacenavButtonAction::SwitchHand:
      if (event.pressed) switchHand();
      break;
    case SpacenavButtonAction::SwitchInstrument:
      if (event.pressed) switchActiveInstrument();
      break;
    case SpacenavButtonAction::None: break;
  }
}

}  // namespace microsim::tracking
