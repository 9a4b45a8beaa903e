#pragma once
// OpenIGTLink client: connects to a server (PLUS, 3D Slicer, a tracker's own server),
// reads TRANSFORM, POSITION, TDATA and SENSOR messages, and produces InputFrames through
// the DeviceMapping. The socket lives on the client's own QThread; the GUI thread only
// receives queued signals. Every refusal is counted (IgtlDecoder, PoseFilter); the link
// is never dropped for bad data. When the link goes down (refused, closed, reset) the
// client reconnects after a delay that doubles from reconnectInitialMs up to
// reconnectMaxMs and returns to the initial value once a pose is accepted again.

#include "tracking/frame_assembler.h"
#include "tracking/pose_filter.h"
#include "tracking/tracker_source.h"

#include <QString>
#include <QThread>

#include <cstdint>
#include <memory>

namespace microsim::tracking {

inline constexpr quint16 kIgtlDefaultPort = 18944;

struct IgtlClientConfig {
  QString host = QStringLiteral("127.0.0.1");
  quint16 port = kIgtlDefaultPort;
  DeviceMapping mapping;
  PoseLimits limits;
  bool reconnect = true;                   ///< false: stay down after the first disconnect
  int reconnectInitialMs = 100;            ///< ms, first retry delay
  int reconnectMaxMs = 5000;               ///< ms, longest retry delay
  std::uint64_t maxBodyBytes = 1u << 20;   ///< bytes, larger bodies are taken for garbage
};

class IgtlClient : public TrackerSource {
  Q_OBJECT

 public:
  explicit IgtlClient(IgtlClientConfig config, QObject* parent = nullptr);
  ~IgtlClient() override;

  void start() override;
  void stop() override;
  TrackerStatus status() const override;

  const IgtlClientConfig& config() const { return config_; }

 private:
  class Worker;
  struct Shared;

  IgtlClientConfig config_;
  std::shared_ptr<Shared> shared_;
  QThread thread_;
  Worker* worker_ = nullptr;  // lives and dies on thread_ (deleted there as it finishes)
};

/// Parses "HOST:PORT" (PORT optional, default 18944). False on a malformed port.
bool parseHostPort(const QString& text, QString& host, quint16& port);

}  // namespace microsim::tracking
