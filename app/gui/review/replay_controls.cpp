#include "gui/review/replay_controls.h"

#include "gui/review/replay_event_scan.h"
#include "gui/review/replay_marks.h"
#include "gui/review/replay_player.h"
#include "gui/review/replay_timeline.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QShortcut>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

namespace microsim::gui {

namespace {

QToolButton* transportButton(QStyle::StandardPixmap icon, const QString& tip, const QString& name) {
  auto* button = new QToolButton;
  button->setIcon(button->style()->standardIcon(icon));
  button->setToolTip(tip);
  button->setAccessibleName(tip);
  button->setObjectName(name);
  button->setAutoRaise(true);
  return button;
}

}  // namespace

const std::vector<double>& ReplayControls::speeds() {
  static const std::vector<double> offered{0.25, 0.5, 1.0, 2.0, 4.0};
  return offered;
}

ReplayControls::ReplayControls(ReplayPlayer* player, QWidget* parent)
    : QWidget(parent), player_(player), scan_(new ReplayEventScan(this)) {
  toStart_ = transportButton(QStyle::SP_MediaSkipBackward, tr("To the start (Home)"), QStringLiteral("replayToStart"));
  stepBack_ = transportButton(QStyle::SP_MediaSeekBackward, tr("One frame back (Left)"), QStringLiteral("replayStepBack"));
  play_ = transportButton(QStyle::SP_MediaPlay, tr("Play (Space)"), QStringLiteral("replayPlay"));
  stepForward_ = transportButton(QStyle::SP_MediaSeekForward, tr("One frame on (Right)"), QStringLiteral("replayStepForward"));
  toEnd_ = transportButton(QStyle::SP_MediaSkipForward, tr("To the end (End)"), QStringLiteral("replayToEnd"));

  slider_ = new QSlider(Qt::Horizontal);
  slider_->setObjectName(QStringLiteral("replaySlider"));
  slider_->setAccessibleName(tr("Replay position"));
  time_ = new QLabel;
  time_->setObjectName(QStringLiteral("replayTime"));
  speed_ = new QComboBox;
  speed_->setObjectName(QStringLiteral("replaySpeed"));
  speed_->setToolTip(tr("Playback speed"));
  const QLocale locale;
  for (double s : speeds()) speed_->addItem(tr("%1×").arg(locale.toString(s)), s);
  speed_->setCurrentIndex(speed_->findData(1.0));
  rerun_ = new QProgressBar;
  rerun_->setObjectName(QStringLiteral("replayRerun"));
  rerun_->setFormat(tr("Stepping from the start: %p%"));
  rerun_->setMaximumHeight(rerun_->fontMetrics().height() + 4);
  rerun_->hide();
  timeline_ = new ReplayTimeline;
  timeline_->setObjectName(QStringLiteral("replayTimeline"));

  auto* transport = new QHBoxLayout;
  transport->setContentsMargins(0, 0, 0, 0);
  for (QToolButton* b : {toStart_, stepBack_, play_, stepForward_, toEnd_}) transport->addWidget(b);
  transport->addWidget(time_, 1);
  transport->addWidget(speed_);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(2);
  layout->addWidget(slider_);
  layout->addWidget(timeline_);
  layout->addWidget(rerun_);
  layout->addLayout(transport);

  // what is asked of the player
  connect(play_, &QToolButton::clicked, player_, &ReplayPlayer::togglePlay);
  connect(toStart_, &QToolButton::clicked, player_, [this] { player_->seek(0); });
  connect(stepBack_, &QToolButton::clicked, player_, &ReplayPlayer::stepBackward);
  connect(stepForward_, &QToolButton::clicked, player_, &ReplayPlayer::stepForward);
  connect(toEnd_, &QToolButton::clicked, player_, &ReplayPlayer::skipToEnd);
  connect(speed_, &QComboBox::currentIndexChanged, this,
          [this](int index) { player_->setSpeed(speed_->itemData(index).toDouble()); });
  // a drag only shows where it is; the seek follows the release (each seek backward steps from the start)
  connect(slider_, &QSlider::valueChanged, this, [this](int value) {
    if (!slider_->isSliderDown()) player_->seek(value);
  });
  connect(slider_, &QSlider::sliderMoved, this, &ReplayControls::showTime);
  connect(slider_, &QSlider::sliderReleased, this, [this] { player_->seek(slider_->value()); });
  connect(timeline_, &ReplayTimeline::markClicked, player_, &ReplayPlayer::seek);

  // what the player reports
  connect(player_, &ReplayPlayer::positionChanged, this, &ReplayControls::showPosition);
  connect(player_, &ReplayPlayer::settled, this, &ReplayControls::showPosition);
  connect(player_, &ReplayPlayer::playingChanged, this, &ReplayControls::showPlaying);
  connect(player_, &ReplayPlayer::rerunningChanged, this, &ReplayControls::showRerunning);
  connect(scan_, &ReplayEventScan::finished, this,
          [this] { timeline_->setMarks(replayMarks(scan_->events()), player_->frameCount()); });
}

ReplayControls::~ReplayControls() = default;

void ReplayControls::recordingLoaded() {
  timeline_->clear();
  setEnabled(true);
  {
    const QSignalBlocker block(slider_);
    slider_->setRange(0, player_->frameCount());
    slider_->setPageStep(std::max(1, player_->frameCount() / 20));
  }
  showPlaying(player_->isPlaying());
  showRerunning(player_->isRerunning());
  showPosition(player_->position());
  if (player_->sceneDef()) scan_->start(*player_->sceneDef(), player_->frames());
}

void ReplayControls::recordingUnloaded() {
  scan_->cancel();
  timeline_->clear();
  setEnabled(false);
}

void ReplayControls::addShortcuts(QWidget* scope) {
  const auto add = [scope](int key, auto slot) {
    auto* shortcut = new QShortcut(QKeySequence(key), scope);
    shortcut->setContext(Qt::WidgetWithChildrenShortcut);
    connect(shortcut, &QShortcut::activated, shortcut, slot);
  };
  add(Qt::Key_Space, [this] { player_->togglePlay(); });
  add(Qt::Key_Left, [this] { player_->stepBackward(); });
  add(Qt::Key_Right, [this] { player_->stepForward(); });
  add(Qt::Key_Home, [this] { player_->seek(0); });
  add(Qt::Key_End, [this] { player_->skipToEnd(); });
}

void ReplayControls::showPosition(int position) {
  // during a rerun from the start the slider stays where it was asked to go; the bar moves
  const int shown = player_->isRerunning() ? player_->target() : position;
  if (player_->isRerunning()) rerun_->setValue(position);
  if (!slider_->isSliderDown()) {
    const QSignalBlocker block(slider_);
    slider_->setValue(shown);
  }
  timeline_->setPosition(shown);
  showTime(shown);
}

void ReplayControls::showTime(int position) {
  const QLocale locale;
  time_->setText(tr("%1 / %2 s").arg(locale.toString(player_->timeAt(position), 'f', 2),
                                     locale.toString(player_->timeAt(player_->frameCount()), 'f', 2)));
}

void ReplayControls::showPlaying(bool playing) {
  play_->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
  const QString tip = playing ? tr("Pause (Space)") : tr("Play (Space)");
  play_->setToolTip(tip);
  play_->setAccessibleName(tip);
}

void ReplayControls::showRerunning(bool rerunning) {
  rerun_->setRange(0, std::max(1, player_->target()));
  rerun_->setValue(player_->position());
  rerun_->setVisible(rerunning);
}

}  // namespace microsim::gui
