#include "tracking/replay_source.h"

#include <QFile>
#include <QMutexLocker>

#include <algorithm>
#include <cmath>

namespace microsim::tracking {

namespace {

void registerTypes() {
  qRegisterMetaType<sim::InputFrame>();
  qRegisterMetaType<RawPose>();
  qRegisterMetaType<ChannelValue>();
  qRegisterMetaType<Rejection>();
}

}  // namespace

ReplaySource::ReplaySource(PoseStream stream, ReplayConfig config, QObject* parent)
    : TrackerSource(parent),
      config_(std::move(config)),
      stream_(std::move(stream)),
      filter_(config_.limits),
      assembler_(config_.mapping) {
  registerTypes();
  timer_.setSingleShot(true);
  connect(&timer_, &QTimer::timeout, this, &ReplaySource::tick);
}

ReplaySource::ReplaySource(std::vector<sim::InputFrame> frames, ReplayConfig config, QObject* parent)
    : ReplaySource(PoseStream{}, std::move(config), parent) {
  frames_ = std::move(frames);
  rawStream_ = false;
}

// qualified: a destructor cannot dispatch to an override, say so
ReplaySource::~ReplaySource() { ReplaySource::stop(); }

std::size_t ReplaySource::sampleCount() const { return rawStream_ ? stream_.samples.size() : frames_.size(); }

double ReplaySource::dueTime(std::size_t i) const {
  if (rawStream_) return sampleTime(stream_.samples[i]) - sampleTime(stream_.samples.front());
  return frames_[i].time - frames_.front().time;
}

void ReplaySource::start() {
  if (running_) return;
  running_ = true;
  next_ = 0;
  lastFrameTime_ = 0.0;
  filter_.reset();
  assembler_ = FrameAssembler(config_.mapping);
  recent_.clear();
  {
    QMutexLocker lock(&mutex_);
    status_ = {};
    status_.connected = true;
    status_.connections = 1;
  }
  clock_.start();
  Q_EMIT connectedChanged(true);
  timer_.start(0);
}

void ReplaySource::stop() {
  timer_.stop();
  if (!running_) return;
  running_ = false;
  {
    QMutexLocker lock(&mutex_);
    status_.connected = false;
    status_.rateHz = 0.0;
  }
}

TrackerStatus ReplaySource::status() const {
  QMutexLocker lock(&mutex_);
  return status_;
}

void ReplaySource::tick() {
  if (!running_) return;
  // every sample that is due (real time) or the next batch (as fast as possible)
  const double elapsed = static_cast<double>(clock_.nsecsElapsed()) * 1e-9;
  const std::size_t n = sampleCount();
  int emitted = 0;
  while (running_ && next_ < n) {
    if (config_.pace == ReplayPace::RealTime ? dueTime(next_) > elapsed : emitted >= std::max(config_.batch, 1)) break;
    play(next_++);
    ++emitted;
  }
  if (!running_) return;
  if (next_ < n) {
    const double wait = config_.pace == ReplayPace::RealTime ? dueTime(next_) - elapsed : 0.0;
    timer_.start(static_cast<int>(std::ceil(std::max(wait, 0.0) * 1000.0)));
    return;
  }

  // the end of the file: the link goes down as a live one would
  running_ = false;
  {
    QMutexLocker lock(&mutex_);
    status_.connected = false;
    status_.rateHz = 0.0;
  }
  Q_EMIT connectedChanged(false);
  Q_EMIT linkDown();
  Q_EMIT finished();
}

void ReplaySource::play(std::size_t i) {
  const double t = dueTime(i);
  if (rawStream_) {
    playSample(stream_.samples[i], t);
    return;
  }
  sim::InputFrame frame = frames_[i];
  frame.time = t;
  emitFrame(frame);
}

void ReplaySource::playSample(const StreamSample& sample, double frameTime) {
  if (const auto* pose = std::get_if<RawPose>(&sample)) {
    if (const std::optional<Rejection> why = filter_.check(*pose)) {
      reject(*why);
      return;
    }
    recent_.push_back(frameTime);
    while (recent_.front() < frameTime - 1.0) recent_.pop_front();
    {
      QMutexLocker lock(&mutex_);
      ++status_.accepted;
      status_.rateHz = static_cast<double>(recent_.size());
    }
    Q_EMIT poseAccepted(*pose);
    if (std::optional<sim::InputFrame> frame = assembler_.applyPose(*pose, frameTime)) emitFrame(*frame);
    return;
  }
  const ChannelValue& value = std::get<ChannelValue>(sample);
  if (const std::optional<Rejection> why = filter_.check(value)) {
    reject(*why);
    return;
  }
  Q_EMIT channelAccepted(value);
  if (std::optional<sim::InputFrame> frame = assembler_.applyChannel(value, frameTime)) emitFrame(*frame);
}

void ReplaySource::emitFrame(const sim::InputFrame& frame) {
  sim::InputRejection why{};
  if (!sim::validateSequence(frame, lastFrameTime_, why)) {
    reject(Rejection::InvalidFrame);
    return;
  }
  lastFrameTime_ = frame.time;
  if (!rawStream_) {
    recent_.push_back(frame.time);
    while (recent_.front() < frame.time - 1.0) recent_.pop_front();
    QMutexLocker lock(&mutex_);
    ++status_.accepted;
    status_.rateHz = static_cast<double>(recent_.size());
  }
  Q_EMIT frameReady(frame);
}

void ReplaySource::reject(Rejection r) {
  {
    QMutexLocker lock(&mutex_);
    status_.rejected.add(r);
  }
  Q_EMIT rejected(r);
}

std::unique_ptr<ReplaySource> openReplay(const QString& path, ReplayConfig config, ReplayFileStatus& status,
                                         QObject* parent) {
  status = {};
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) {
    status.error = ReplayFileError::CannotOpen;
    return nullptr;
  }
  const QByteArray bytes = f.readAll();

  // a simulation recording, known by its magic
  static const QByteArray magic("MSIMREC\x1a", 8);
  if (bytes.startsWith(magic)) {
    sim::Recording recording;
    const sim::RecordingStatus rs = sim::decodeRecording(
        {reinterpret_cast<const std::uint8_t*>(bytes.constData()), static_cast<std::size_t>(bytes.size())}, recording);
    status.recording = rs.error;
    if (!rs.ok() && rs.error != sim::RecordingError::Truncated) {
      status.error = ReplayFileError::Damaged;
      return nullptr;
    }
    return std::make_unique<ReplaySource>(std::move(recording.frames), std::move(config), parent);
  }

  // a raw tracker stream
  PoseStream stream;
  status.stream = decodePoseStream(bytes, stream);
  // like an unfinished .msrec: a stream cut short plays its complete samples
  if (!status.stream.ok() && status.stream.error != PoseStreamError::Truncated) {
    status.error = status.stream.error == PoseStreamError::BadSample ? ReplayFileError::Damaged : ReplayFileError::NotAReplay;
    return nullptr;
  }
  return std::make_unique<ReplaySource>(std::move(stream), std::move(config), parent);
}

}  // namespace microsim::tracking
