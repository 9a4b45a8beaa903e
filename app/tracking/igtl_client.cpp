#include "tracking/igtl_client.h"

#include "tracking/igtl_decoder.h"

#include <QElapsedTimer>
#include <QTcpSocket>
#include <QTimer>

#include <algorithm>
#include <deque>
#include <mutex>
#include <optional>

namespace microsim::tracking {

// std::mutex rather than QMutex: ThreadSanitizer follows it in every case, while QMutex's
// contended path runs inside Qt, which is not instrumented
struct IgtlClient::Shared {
  mutable std::mutex mutex;
  TrackerStatus status;
};

// lives on the client's thread: owns the socket, the decoder, the filter and the assembler
class IgtlClient::Worker : public QObject {
 public:
  Worker(IgtlClient* owner, IgtlClientConfig config, std::shared_ptr<Shared> shared)
      : owner_(owner),
        config_(std::move(config)),
        shared_(std::move(shared)),
        decoder_(config_.maxBodyBytes),
        filter_(config_.limits),
        assembler_(config_.mapping),
        backoffMs_(config_.reconnectInitialMs) {}

  void begin() {
    clock_.start();
    socket_ = new QTcpSocket(this);
    retry_ = new QTimer(this);
    retry_->setSingleShot(true);
    QObject::connect(retry_, &QTimer::timeout, this, [this] { connectNow(); });
    QObject::connect(socket_, &QTcpSocket::connected, this, [this] { onConnected(); });
    QObject::connect(socket_, &QTcpSocket::readyRead, this, [this] { onReadyRead(); });
    QObject::connect(socket_, &QAbstractSocket::errorOccurred, this, [this](QAbstractSocket::SocketError) {
      const std::lock_guard lock(shared_->mutex);
      shared_->status.lastError = socket_->errorString();
    });
    QObject::connect(socket_, &QAbstractSocket::stateChanged, this, [this](QAbstractSocket::SocketState s) {
      if (s == QAbstractSocket::UnconnectedState) onLinkDown();
    });
    connectNow();
  }

  // stops the retries and closes the socket; nothing is emitted afterwards
  void end() {
    stopping_ = true;
    if (retry_ != nullptr) retry_->stop();
    if (socket_ != nullptr) {
      socket_->disconnect(this);
      socket_->abort();
    }
    delete socket_;
    delete retry_;
    socket_ = nullptr;
    retry_ = nullptr;
  }

 private:
  double now() const { return static_cast<double>(clock_.nsecsElapsed()) * 1e-9; }

  void connectNow() {
    if (stopping_) return;
    socket_->connectToHost(config_.host, config_.port);
  }

  void onConnected() {
    socket_->setSocketOption(QAbstractSocket::LowDelayOption, 1);
    // a new connection may restart the server's clock: fresh references and time offset
    filter_.reset();
    timeOffset_.reset();
    {
      const std::lock_guard lock(shared_->mutex);
      shared_->status.connected = true;
      ++shared_->status.connections;
    }
    Q_EMIT owner_->connectedChanged(true);
  }

  void onReadyRead() {
    const QByteArray bytes = socket_->readAll();
    decoder_.feed({reinterpret_cast<const std::uint8_t*>(bytes.constData()), static_cast<std::size_t>(bytes.size())},
                  now(), out_);
    deliver();
  }

  void onLinkDown() {
    if (stopping_) return;
    // bytes still buffered in the socket, then whatever is left half-read is truncated
    const QByteArray rest = socket_->readAll();
    if (!rest.isEmpty())
      decoder_.feed({reinterpret_cast<const std::uint8_t*>(rest.constData()), static_cast<std::size_t>(rest.size())},
                    now(), out_);
    decoder_.endOfStream(out_);
    deliver();

    bool wasConnected = false;
    {
      const std::lock_guard lock(shared_->mutex);
      wasConnected = shared_->status.connected;
      shared_->status.connected = false;
      shared_->status.rateHz = 0.0;
    }
    if (wasConnected) {
      Q_EMIT owner_->connectedChanged(false);
      emitFrame(assembler_.lose(std::max(lastFrameTime_, now())));
    }
    Q_EMIT owner_->linkDown();
    if (!config_.reconnect) return;
    retry_->start(backoffMs_);
    backoffMs_ = std::min(backoffMs_ * 2, config_.reconnectMaxMs);
  }

  // hands the decoder's output, in stream order, through the filter and the assembler
  void deliver() {
    const double t = now();
    for (const IgtlDecodeOutput::Item& item : out_.order) {
      switch (item.kind) {
        case IgtlDecodeOutput::Kind::Rejection: reject(out_.rejections[item.index]); break;
        case IgtlDecodeOutput::Kind::Pose: acceptPose(out_.poses[item.index], t); break;
        case IgtlDecodeOutput::Kind::Channel: acceptChannel(out_.channels[item.index], t); break;
      }
    }
    out_.clear();
  }

  void acceptPose(const RawPose& pose, double t) {
    if (const std::optional<Rejection> why = filter_.check(pose)) {
      reject(*why);
      return;
    }
    accepted_.push_back(t);
    backoffMs_ = config_.reconnectInitialMs;
    {
      const std::lock_guard lock(shared_->mutex);
      ++shared_->status.accepted;
      while (!accepted_.empty() && accepted_.front() < t - 1.0) accepted_.pop_front();
      shared_->status.rateHz = static_cast<double>(accepted_.size());
    }
    Q_EMIT owner_->poseAccepted(pose);
    if (std::optional<sim::InputFrame> frame = assembler_.applyPose(pose, frameTime(pose.time, t))) emitFrame(*frame);
  }

  void acceptChannel(const ChannelValue& value, double t) {
    if (const std::optional<Rejection> why = filter_.check(value)) {
      reject(*why);
      return;
    }
    Q_EMIT owner_->channelAccepted(value);
    if (std::optional<sim::InputFrame> frame = assembler_.applyChannel(value, frameTime(value.time, t)))
      emitFrame(*frame);
  }

  // source time mapped onto the client's clock; the offset is fixed per connection and
  // starts no earlier than the last frame, so frames never go back across reconnections
  double frameTime(double sourceTime, double receiveTime) {
    if (!timeOffset_) timeOffset_ = std::max(receiveTime, lastFrameTime_) - sourceTime;
    return sourceTime + *timeOffset_;
  }

  void emitFrame(const sim::InputFrame& frame) {
    sim::InputRejection why{};
    if (!sim::validateSequence(frame, lastFrameTime_, why)) {
      reject(Rejection::InvalidFrame);
      return;
    }
    lastFrameTime_ = frame.time;
    Q_EMIT owner_->frameReady(frame);
  }

  void reject(Rejection r) {
    {
      const std::lock_guard lock(shared_->mutex);
      shared_->status.rejected.add(r);
    }
    Q_EMIT owner_->rejected(r);
  }

  IgtlClient* owner_;
  IgtlClientConfig config_;
  std::shared_ptr<Shared> shared_;
  IgtlDecoder decoder_;
  IgtlDecodeOutput out_;
  PoseFilter filter_;
  FrameAssembler assembler_;
  QTcpSocket* socket_ = nullptr;
  QTimer* retry_ = nullptr;
  QElapsedTimer clock_;
  std::deque<double> accepted_;  ///< receive times (s) of the poses accepted in the last second
  std::optional<double> timeOffset_;
  double lastFrameTime_ = 0.0;
  int backoffMs_;
  bool stopping_ = false;
};

IgtlClient::IgtlClient(IgtlClientConfig config, QObject* parent)
    : TrackerSource(parent), config_(std::move(config)), shared_(std::make_shared<Shared>()) {
  qRegisterMetaType<sim::InputFrame>();
  qRegisterMetaType<RawPose>();
  qRegisterMetaType<ChannelValue>();
  qRegisterMetaType<Rejection>();
  thread_.setObjectName(QStringLiteral("igtl-client"));
}

// qualified: a destructor cannot dispatch to an override, say so
IgtlClient::~IgtlClient() { IgtlClient::stop(); }

void IgtlClient::start() {
  if (worker_ != nullptr) return;
  worker_ = new Worker(this, config_, shared_);
  worker_->moveToThread(&thread_);
  Worker* w = worker_;
  // Every hand-over to and from the worker is ordered by the thread's start and end, not by
  // a blocking queued call: begin() is posted before the thread starts; end() runs on the
  // thread as its event loop finishes (QThread::finished is emitted there), and the worker
  // is deleted there too, before stop()'s wait() returns. So the worker's memory is only
  // ever touched on its own thread, and ThreadSanitizer, which cannot see Qt's event-queue
  // locks (Qt is not instrumented), has nothing to misread.
  QMetaObject::invokeMethod(w, [w] { w->begin(); }, Qt::QueuedConnection);
  connect(&thread_, &QThread::finished, w, &Worker::end, Qt::DirectConnection);
  connect(&thread_, &QThread::finished, w, &QObject::deleteLater);
  thread_.start();
}

void IgtlClient::stop() {
  if (worker_ == nullptr) return;
  thread_.quit();
  thread_.wait();  // the worker has ended and been deleted on the thread
  worker_ = nullptr;
  const std::lock_guard lock(shared_->mutex);
  shared_->status.connected = false;
  shared_->status.rateHz = 0.0;
}

TrackerStatus IgtlClient::status() const {
  const std::lock_guard lock(shared_->mutex);
  return shared_->status;
}

bool parseHostPort(const QString& text, QString& host, quint16& port) {
  const qsizetype colon = text.lastIndexOf(QLatin1Char(':'));
  if (colon < 0) {
    host = text;
    port = kIgtlDefaultPort;
    return !host.isEmpty();
  }
  bool ok = false;
  const uint value = text.mid(colon + 1).toUInt(&ok);
  if (!ok || value == 0 || value > 65535) return false;
  host = text.left(colon);
  port = static_cast<quint16>(value);
  return !host.isEmpty();
}

}  // namespace microsim::tracking
